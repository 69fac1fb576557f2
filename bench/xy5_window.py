#!/usr/bin/env python3
# Window convergence of XY-5 (issue 16): compares two runs' summary.json peak by peak (every
# "value" under buildings_3d and contacts_3d), the impacts per wall at >= 1 mm/s
# (impacts_above_1mm_s) and the first-impact time of each wall. Relative differences are taken against
# the reference's value, over peaks larger than 1e-6 of the largest peak of their unit.
# Usage: python3 bench/xy5_window.py RUN_DIR REFERENCE_DIR
import json
import pathlib
import sys


def leaves(node, path, out):
    if isinstance(node, dict):
        if "value" in node and "unit" in node:
            out[path] = (node["value"], node["unit"])
            return
        for k, v in node.items():
            leaves(v, f"{path}/{k}", out)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            label = v.get("label", str(i)) if isinstance(v, dict) else str(i)
            leaves(v, f"{path}/{label}", out)


def peaks(d):
    j = json.loads((pathlib.Path(d) / "summary.json").read_text())
    out = {}
    leaves(j["buildings_3d"], "", out)
    leaves(j["contacts_3d"], "", out)
    return out


def main():
    run, ref = sys.argv[1], sys.argv[2]
    p, q = peaks(run), peaks(ref)
    scale = {}
    for v, unit in q.values():
        scale[unit] = max(scale.get(unit, 0.0), abs(v))
    worst = (0.0, "")
    for k, (v_ref, unit) in q.items():
        if abs(v_ref) <= 1e-6 * scale[unit]:
            continue
        rel = abs(p[k][0] - v_ref) / abs(v_ref)
        if rel > worst[0]:
            worst = (rel, k)
    sr = json.loads((pathlib.Path(run) / "summary.json").read_text())["contacts_3d"]
    sq = json.loads((pathlib.Path(ref) / "summary.json").read_text())["contacts_3d"]
    same_impacts = all(a["impacts_above_1mm_s"] == b["impacts_above_1mm_s"] for a, b in zip(sr, sq))
    first = 0.0
    for a, b in zip(sr, sq):
        ta, tb = a["first_impact_time_s"], b["first_impact_time_s"]
        if (ta is None) != (tb is None):
            first = float("inf")
        elif ta is not None:
            first = max(first, abs(ta - tb))
    impacts = " ".join(f"{a['impacts_above_1mm_s']}/{b['impacts_above_1mm_s']}"
                       f"({a['impacts']}/{b['impacts']})" for a, b in zip(sr, sq))
    print(f"worst peak {100 * worst[0]:.4f} % ({worst[1]}); impacts >= 1 mm/s per wall run/ref (all impacts) {impacts} "
          f"({'same' if same_impacts else 'DIFFER'}); first impacts within {1e3 * first:.4f} ms")


if __name__ == "__main__":
    main()
