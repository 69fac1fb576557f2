#!/usr/bin/env bash
# XY-5 angle study driver (issue 16): configs/3d-xy5.yaml at incidence angles 0..360 step 5 (73
# runs, `isopound run -q --no-histories`, -P jobs at once), then bench/xy5_collect.py -> peaks.csv.
# Usage: bash bench/xy5_angles.sh OUT_DIR [tolerance|default] [jobs=2] [extra analysis keys]
#   e.g. bash bench/xy5_angles.sh /tmp/xy5-tol1e-5 1e-5 2
#   ANGLES="0 45 120" bash bench/xy5_angles.sh /tmp/w default 2 "t_end: 3.6 s"
# Prints the wall time of the whole batch and the summed CPU time of its runs (out/time.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
out="$(realpath -m "$1")"
tol="${2:-default}"
jobs="${3:-2}"
extra="${4:-}"
bin="$(realpath "${ISOPOUND:-build/isopound}")"
records="$(realpath ../shared/records)"
angles="${ANGLES:-$(seq 0 5 360)}"
mkdir -p "$out/cfg"

analysis=""
[ "$tol" != "default" ] && analysis="tolerance: $tol"
[ -n "$extra" ] && analysis="${analysis:+$analysis, }$extra"
grep -q '^analysis:' configs/3d-xy5.yaml && { echo "3d-xy5.yaml has an analysis section" >&2; exit 2; }
for a in $angles; do
  name=$(printf 'angle-%03d' "$a")
  sed -e "s#\.\./\.\./shared/records#$records#" -e "s#^  angle: .*#  angle: $a deg#" \
    configs/3d-xy5.yaml > "$out/cfg/$name.yaml"
  grep -q "^  angle: $a deg" "$out/cfg/$name.yaml"
  [ -n "$analysis" ] && echo "analysis: {$analysis}" >> "$out/cfg/$name.yaml"
  echo "$name"
done > "$out/cases.txt"

start=$(date +%s.%N)
# Each run's own wall and CPU time: /usr/bin/time into the run's directory.
xargs -P "$jobs" -I{} sh -c "mkdir -p '$out/{}' && nice -n 10 /usr/bin/time -f '%e %U %S' \
  -o '$out/{}/time.txt' '$bin' run -q --no-histories '$out/cfg/{}.yaml' -o '$out/{}'" \
  < "$out/cases.txt"
end=$(date +%s.%N)
python3 - "$out" "$start" "$end" "$jobs" <<'EOF'
import pathlib, sys
out, start, end, jobs = pathlib.Path(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
cpu = 0.0
runs = 0
for t in sorted(out.glob("angle-*/time.txt")):
    w, u, s = map(float, t.read_text().split())
    cpu += u + s
    runs += 1
load = open("/proc/loadavg").read().split()[:3]
line = (f"{runs} runs, -P {jobs}: wall {end - start:.1f} s, CPU (user+sys, summed over runs) "
        f"{cpu:.1f} s, load average after {' '.join(load)}")
print(line)
(out / "time.txt").write_text(line + "\n")
EOF
python3 bench/xy5_collect.py "$out" > "$out/peaks.csv"
echo "wrote $out/peaks.csv"
