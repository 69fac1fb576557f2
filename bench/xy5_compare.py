#!/usr/bin/env python3
# Statistical convergence of the XY-5 angle study (issue 16): the mean over angles of each peak at
# defaults, 10x and 100x tighter tolerance (peaks.csv of bench/xy5_angles.sh), the relative
# differences defaults vs 10x and 10x vs 100x (the noise floor), against the bounds
# (a bound may be relaxed to twice the noise floor where that floor exceeds it). Markdown table.
# Only angles present in all three files are used. Usage:
#   python3 bench/xy5_compare.py default.csv tol1e-5.csv tol1e-6.csv
import csv
import sys

BOUNDS = [  # (column prefix/suffix test, bound, group)
    (lambda c: c.startswith("base_") and c.endswith("_disp"), 0.02, "base displacement"),
    (lambda c: c.endswith("_corner_drift_ratio"), 0.05, "corner drift ratio"),
    (lambda c: c.startswith("floor") and c.endswith("_cm_acc"), 0.10, "floor acceleration"),
    (lambda c: c in ("F_N", "F_T"), 0.10, "contact force"),
    (lambda c: c.endswith("_theta"), 0.15, "rotation"),
]


def load(path):
    return {int(r["angle_deg"]): r for r in csv.DictReader(open(path))}


def main():
    a, b, c = (load(p) for p in sys.argv[1:4])
    angles = sorted(set(a) & set(b) & set(c))
    columns = [k for k in next(iter(a.values())) if k != "angle_deg"]
    print(f"{len(angles)} angles. Columns: mean at defaults | 1e-5 | 1e-6 | defaults vs 1e-5 | "
          f"1e-5 vs 1e-6 (noise floor) | bound | holds")
    print()
    print("| peak | defaults | 1e-5 | 1e-6 | def vs 1e-5 | 1e-5 vs 1e-6 | bound | holds |")
    print("|---|---|---|---|---|---|---|---|")
    for col in columns:
        bound = next(((bd, g) for test, bd, g in BOUNDS if test(col)), None)
        if bound is None and col not in ("base_cm_acc", "impacts", "impact_velocity"):
            continue
        m = [sum(float(x[ang][col]) for ang in angles) / len(angles) for x in (a, b, c)]
        d1 = abs(m[0] - m[1]) / abs(m[1])
        d2 = abs(m[1] - m[2]) / abs(m[2])
        if bound:
            limit = max(bound[0], 2 * d2) if d2 > bound[0] else bound[0]
            holds = "yes" if d1 <= limit else "NO"
            if d2 > bound[0]:
                holds += " (2x noise floor)"
            btxt = f"{100 * bound[0]:.0f} %"
        else:
            holds, btxt = "(info)", "-"
        print(f"| {col} | {m[0]:.5g} | {m[1]:.5g} | {m[2]:.5g} | {100 * d1:.2f} % | "
              f"{100 * d2:.2f} % | {btxt} | {holds} |")


if __name__ == "__main__":
    main()
