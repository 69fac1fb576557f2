#!/usr/bin/env bash
# Runs/s of the chapter-2 study (a subset: the u_y axis up to `to` cm) of this build against one or
# more reference builds (comma-separated), run alternately in the same session with -j 1 and -j 2
# (the order rotated each round), and the export tables of every build compared. Usage:
#   bash bench/study_sweep_compare.sh [build-dir] reference-isopound[,reference2,...] [to] [rounds]
# e.g. bash bench/study_sweep_compare.sh build /work/base-4e93098/build/isopound 1.2 3
#      STUDY=configs/studies/3d-xy5-angles.yaml bash bench/study_sweep_compare.sh build REF - 2
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$(realpath "${1:-build}")/isopound"
IFS=, read -r -a refs <<< "$2"
for k in "${!refs[@]}"; do refs[$k]="$(realpath "${refs[$k]}")"; done
to="${3:-1.2}"
rounds="${4:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
records="$(realpath ../shared/records)"
# STUDY: another study of configs/studies (e.g. 3d-xy5-angles.yaml, all its runs; `to` is then
# ignored); its model and records paths are made absolute.
study="${STUDY:-configs/studies/chapter2.yaml}"
model="$(sed -nE 's/^model: ([^ #]*).*$/\1/p' "$study")"
sed -e "s#^model: .*#model: $(realpath "$(dirname "$study")/$model")#" \
    -e "s#../../../shared/records#$records#" \
    -e "s#to: 3 cm, step: 0.05 cm#to: $to cm, step: 0.05 cm#" "$study" \
    > "$work/chapter2.yaml"
runs=$("$bin" sweep "$work/chapter2.yaml" --dry-run | head -1 | sed -E 's/.*: ([0-9]+) runs.*/\1/')
echo "$(basename "$study"), u_y to $to cm (chapter 2): $runs runs; $rounds rounds; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
binaries=("$bin" "${refs[@]}")
tags=(new)
for k in "${!refs[@]}"; do tags+=("ref$k"); echo "ref$k = ${refs[$k]}"; done
one() {  # binary tag jobs
  rm -f "$work/$2.db"*
  /usr/bin/time -f "%e %U %S" -o "$work/t" "$1" sweep "$work/chapter2.yaml" -q -j "$3" --db "$work/$2.db"
  echo "$2 $3 $(cat "$work/t")" >> "$work/times"
}
count=${#binaries[@]}
for ((r = 0; r < rounds; ++r)); do
  for j in 1 2; do
    for ((m = 0; m < count; ++m)); do
      b=$(((m + r) % count))
      one "${binaries[$b]}" "${tags[$b]}" "$j"
    done
  done
done
python3 - "$work/times" "$runs" "${tags[@]}" <<'PY'
import sys, statistics
rows = [l.split() for l in open(sys.argv[1])]
runs = int(sys.argv[2])
tags = sys.argv[3:]
for j in ("1", "2"):
    out = {}
    for tag in tags:
        walls = [float(r[2]) for r in rows if r[0] == tag and r[1] == j]
        cpu = [float(r[3]) + float(r[4]) for r in rows if r[0] == tag and r[1] == j]
        out[tag] = (statistics.median(walls), statistics.median(cpu))
        print(f"-j {j} {tag}: median wall {out[tag][0]:.2f} s = {runs / out[tag][0]:.1f} runs/s, "
              f"CPU {1000 * out[tag][1] / runs:.2f} ms/run  (walls {', '.join(f'{w:.2f}' for w in walls)})")
    for tag in tags[1:]:
        print(f"-j {j} runs/s new/{tag}: {out[tag][0] / out['new'][0]:.2f} "
              f"(CPU per run: {out[tag][1] / out['new'][1]:.2f})")
PY
"$bin" export "$work/new.db" -o "$work/tnew" > /dev/null
for k in "${!refs[@]}"; do
  "${refs[$k]}" export "$work/ref$k.db" -o "$work/tref$k" > /dev/null
  for f in "$work/tref$k"/*.csv; do
    cmp -s "$f" "$work/tnew/$(basename "$f")" && echo "ref$k $(basename "$f") identical" ||
      echo "ref$k $(basename "$f") DIFFERS"
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
