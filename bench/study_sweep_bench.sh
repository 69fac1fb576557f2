#!/usr/bin/env bash
# Sweep benchmark: runs/s of the chapter-2 study (RSN1084 pair) with -j 1 and -j 2, and max RSS
# at two study sizes (memory must not grow with the number of runs). Usage:
#   bash bench/study_sweep_bench.sh [build-dir] [fraction]    (fraction of the u_y axis, default 1 = 8856 runs)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
bin="$(realpath "$build")/isopound"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
study="$(realpath configs/studies/chapter2.yaml)"
records="$(realpath ../shared/records)"

# The chapter-2 study, optionally with fewer u_y values (same per-run cost).
to="${2:-3}"
sed -e "s#model: ../thesis-3storey-bw.yaml#model: $(realpath configs/thesis-3storey-bw.yaml)#" \
    -e "s#../../../shared/records#$records#" \
    -e "s#to: 3 cm, step: 0.05 cm#to: $to cm, step: 0.05 cm#" "$study" > "$work/chapter2.yaml"
runs=$("$bin" sweep "$work/chapter2.yaml" --dry-run | head -1 | sed -E 's/.*: ([0-9]+) runs.*/\1/')
echo "chapter-2 study: $runs runs; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"

for j in 1 2; do
  /usr/bin/time -v "$bin" sweep "$work/chapter2.yaml" -q -j "$j" --db "$work/j$j.db" 2> "$work/time$j.txt"
  wall=$(grep "Elapsed (wall clock)" "$work/time$j.txt" | awk '{print $NF}')
  user=$(grep "User time" "$work/time$j.txt" | awk '{print $NF}')
  rss=$(grep "Maximum resident" "$work/time$j.txt" | awk '{print $NF}')
  secs=$(python3 -c "t='$wall'.split(':'); print(sum(float(x)*60**i for i,x in enumerate(reversed(t))))")
  python3 -c "print(f'-j $j: wall {float($secs):.1f} s, {int($runs)/float($secs):.1f} runs/s, user CPU {float($user):.1f} s ({1000*float($user)/int($runs):.2f} ms/run), max RSS $rss KB')"
done
"$bin" export "$work/j1.db" -o "$work/t1" > /dev/null
"$bin" export "$work/j2.db" -o "$work/t2" > /dev/null
cmp -s "$work/t1/runs.csv" "$work/t2/runs.csv" && echo "runs.csv identical for -j 1 and -j 2" || echo "runs.csv DIFFERS"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

# Memory of one process at three sizes: 1,000, 10,000 and 30,000 runs of a short pulse.
for n in 10 100 300; do
  cat > "$work/memory$n.yaml" <<EOF
model: $(realpath configs/thesis-3storey-bw.yaml)
set: {ground_motion.pulse: {duration: 4 s, dt: 0.01 s}}
axes:
  - {name: i, path: ground_motion.pulse.amplitude, range: {from: 0.5 m/s, to: 1.49 m/s, step: 0.01 m/s}}
  - {path: building.isolator.uy, range: {from: 1 cm, to: $(python3 -c "print(1 + ($n - 1) * 0.02)") cm, step: 0.02 cm}}
EOF
  /usr/bin/time -v "$bin" sweep "$work/memory$n.yaml" -q -j 2 --db "$work/memory$n.db" 2> "$work/mem$n.txt"
  echo "$((n * 100)) runs: max RSS $(grep "Maximum resident" "$work/mem$n.txt" | awk '{print $NF}') KB"
done
