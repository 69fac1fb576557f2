#!/usr/bin/env bash
# Runs/s of the chapter-2 study (a subset: the u_y axis up to `to` cm) of this build against a
# reference build, run alternately in the same session with -j 1 and -j 2 (the order swapped each
# round), and the export tables of both compared. Usage:
#   bash bench/study_sweep_compare.sh [build-dir] reference-isopound [to] [rounds]
# e.g. bash bench/study_sweep_compare.sh build /work/base-4e93098/build/isopound 1.2 3
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$(realpath "${1:-build}")/isopound"
ref="$(realpath "$2")"
to="${3:-1.2}"
rounds="${4:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
records="$(realpath ../shared/records)"
sed -e "s#model: ../thesis-3storey-bw.yaml#model: $(realpath configs/thesis-3storey-bw.yaml)#" \
    -e "s#../../../shared/records#$records#" \
    -e "s#to: 3 cm, step: 0.05 cm#to: $to cm, step: 0.05 cm#" configs/studies/chapter2.yaml \
    > "$work/chapter2.yaml"
runs=$("$bin" sweep "$work/chapter2.yaml" --dry-run | head -1 | sed -E 's/.*: ([0-9]+) runs.*/\1/')
echo "chapter-2 study, u_y to $to cm: $runs runs; $rounds rounds; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
one() {  # binary tag jobs
  rm -f "$work/$2.db"*
  /usr/bin/time -f "%e %U %S" -o "$work/t" "$1" sweep "$work/chapter2.yaml" -q -j "$3" --db "$work/$2.db"
  echo "$2 $3 $(cat "$work/t")" >> "$work/times"
}
for ((r = 0; r < rounds; ++r)); do
  for j in 1 2; do
    if ((r % 2 == 0)); then one "$bin" new "$j"; one "$ref" ref "$j"; else one "$ref" ref "$j"; one "$bin" new "$j"; fi
  done
done
python3 - "$work/times" "$runs" <<'PY'
import sys, statistics
rows = [l.split() for l in open(sys.argv[1])]
runs = int(sys.argv[2])
for j in ("1", "2"):
    out = {}
    for tag in ("new", "ref"):
        walls = [float(r[2]) for r in rows if r[0] == tag and r[1] == j]
        cpu = [float(r[3]) + float(r[4]) for r in rows if r[0] == tag and r[1] == j]
        out[tag] = (statistics.median(walls), statistics.median(cpu))
        print(f"-j {j} {tag}: median wall {out[tag][0]:.2f} s = {runs / out[tag][0]:.1f} runs/s, "
              f"CPU {1000 * out[tag][1] / runs:.2f} ms/run  (walls {', '.join(f'{w:.2f}' for w in walls)})")
    print(f"-j {j} runs/s new/ref: {out['ref'][0] / out['new'][0]:.2f} (CPU per run: {out['ref'][1] / out['new'][1]:.2f})")
PY
"$bin" export "$work/new.db" -o "$work/tnew" > /dev/null
"$ref" export "$work/ref.db" -o "$work/tref" > /dev/null
for f in "$work"/tref/*.csv; do
  cmp -s "$f" "$work/tnew/$(basename "$f")" && echo "$(basename "$f") identical" || echo "$(basename "$f") DIFFERS"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
