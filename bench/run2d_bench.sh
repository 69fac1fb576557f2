#!/usr/bin/env bash
# A plain 2D analysis, whole process (issue 39): `isopound run <config> --no-histories` of this
# build against a reference build, run alternately (the machine's load moves both alike), and the
# instructions of one run of each under callgrind, which no load moves: a 12 % slower run of
# the record reader read twice showed as +16 % instructions. Usage:
#   bash bench/run2d_bench.sh [build-dir] [reference-isopound] [rounds] [config]
# e.g. bash bench/run2d_bench.sh build /work/base-86b43ab/build/isopound 20
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$(realpath "${1:-build}")/isopound"
ref="${2:-}"
rounds="${3:-20}"
config="$(realpath "${4:-configs/thesis-3storey-bl.yaml}")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
binaries=("$bin")
[ -n "$ref" ] && binaries+=("$(realpath "$ref")")
echo "$(basename "$config") --no-histories, $rounds alternating rounds; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 0; r < rounds; ++r)); do
  for i in "${!binaries[@]}"; do
    s=$(date +%s%N)
    "${binaries[$i]}" run "$config" --no-histories -q -o "$work/out$i" > /dev/null
    echo "$i $(( ($(date +%s%N) - s) / 1000 ))" >> "$work/times"
  done
done
python3 - "$work/times" "${binaries[@]}" <<'PY'
import sys, statistics
times = {}
for line in open(sys.argv[1]):
    i, us = line.split()
    times.setdefault(int(i), []).append(int(us) / 1000)
names = sys.argv[2:]
for i, name in enumerate(names):
    t = sorted(times[i])
    print(f"{name}: median {statistics.median(t):.1f} ms, best {t[0]:.1f} ms")
if len(names) == 2:
    print(f"ratio this/reference: median {statistics.median(times[0]) / statistics.median(times[1]):.3f}, "
          f"best {min(times[0]) / min(times[1]):.3f}")
PY
if command -v valgrind > /dev/null; then
  for i in "${!binaries[@]}"; do
    valgrind --tool=callgrind --callgrind-out-file="$work/cg$i" "${binaries[$i]}" run "$config" \
      --no-histories -q -o "$work/cgout$i" 2>&1 | sed -nE 's/.*Collected : ([0-9]+)/\1/p' > "$work/ir$i"
    echo "${binaries[$i]}: $(cat "$work/ir$i") instructions (callgrind)"
  done
  [ ${#binaries[@]} = 2 ] && python3 -c "print(f'instructions this/reference: {int(open(\"$work/ir0\").read()) / int(open(\"$work/ir1\").read()):.3f}')"
fi
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
