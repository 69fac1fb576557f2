#!/usr/bin/env python3
# Collects the peaks of an XY-5 angle study (bench/xy5_angles.sh: OUT/angle-NNN/summary.json) into
# one CSV row per angle (SI: m, rad, m/s2, N, J), plus each run's passivity and dissipation checks.
# Usage: python3 bench/xy5_collect.py OUT_DIR > peaks.csv
import csv
import json
import pathlib
import sys


def value(peak):
    return peak["value"]


def row(summary):
    b = summary["buildings_3d"][0]
    r = {}
    for level in b["levels"]:
        name = level["label"].replace(" ", "")  # base, floor1, ...
        cm = level["centre_of_mass"]
        r[f"{name}_cm_disp"] = value(cm["displacement"]["resultant"])
        r[f"{name}_corner_disp"] = max(value(c["displacement"]["resultant"]) for c in level["corners"])
        r[f"{name}_cm_acc"] = value(cm["absolute_acceleration"]["resultant"])
        r[f"{name}_theta"] = value(level["theta"])
    for storey in b["storeys"]:
        name = storey["label"].replace(" ", "")  # story1, ...
        r[f"{name}_corner_drift_ratio"] = max(
            value(c["drift_ratio"]) for c in storey["corner_columns"].values())
    contacts = summary["contacts_3d"]
    r["F_N"] = max(value(c["normal_force"]) for c in contacts)
    r["F_T"] = max(value(c["tangential_force"]) for c in contacts)
    r["impacts"] = sum(c["impacts"] for c in contacts)
    r["impact_velocity"] = max(value(c["impact_velocity"]) for c in contacts)
    # Passivity: per contact episode the net work on the structures (<= 0), the run's dissipation.
    r["episodes"] = sum(c["episodes"] for c in contacts)
    works = [c["max_episode_net_work_J"] for c in contacts if c["max_episode_net_work_J"] is not None]
    rel = [c["max_episode_net_work_relative"] for c in contacts
           if c["max_episode_net_work_relative"] is not None]
    r["max_episode_net_work_J"] = max(works) if works else ""
    r["max_episode_net_work_relative"] = max(rel) if rel else ""
    r["min_friction_dissipated_J"] = min(c["friction_dissipated_J"] for c in contacts)
    r["min_impact_dissipated_J"] = min(c["impact_dissipated_J"] for c in contacts)
    e = summary["energy"]
    r["run_friction_dissipated_J"] = e["friction_dissipated_J"]
    r["run_impact_dissipated_J"] = e["impact_dissipated_J"]
    r["energy_relative_error"] = e["relative_error"]
    s = summary["statistics"]
    r["steps"] = s["steps"]
    r["wall_seconds"] = s["wall_seconds"]
    r["analysed_time_s"] = s["analysed_time_s"]
    return r


def main():
    out = pathlib.Path(sys.argv[1])
    rows = []
    for d in sorted(out.glob("angle-*")):
        if not d.is_dir():
            continue
        f = d / "summary.json"
        if not f.exists():
            sys.exit(f"{f}: missing (the run failed?)")
        r = {"angle_deg": int(d.name.split("-")[1])}
        r.update(row(json.loads(f.read_text())))
        rows.append(r)
    w = csv.DictWriter(sys.stdout, fieldnames=list(rows[0].keys()), lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in r.items()})


if __name__ == "__main__":
    main()
