#!/usr/bin/env bash
# Window convergence of XY-5 (issue 16): per angle, configs/3d-xy5.yaml run to t_end 3.6 s at
# defaults and at fixed steps 0.005/1024 s (the reference) and 0.005/2048 s (its halving, which
# shows the reference converged), one process at a time; bench/xy5_window.py compares them.
# Usage: bash bench/xy5_window.sh OUT_DIR [angles...]   (default angles: 0 45 120)
set -euo pipefail
cd "$(dirname "$0")/.."
out="$(realpath -m "$1")"
shift
angles="${*:-0 45 120}"
bin="$(realpath "${ISOPOUND:-build/isopound}")"
records="$(realpath ../shared/records)"
mkdir -p "$out"
for a in $angles; do
  base="$out/a$a"
  sed -e "s#\.\./\.\./shared/records#$records#" -e "s#^  angle: .*#  angle: $a deg#" \
    configs/3d-xy5.yaml > "$base.yaml"
  nice -n 10 "$bin" run -q --no-histories --until 3.6 "$base.yaml" -o "$base-default"
  # The light test's comparison run (tests/pounding3d_passivity_test.cpp): tolerance 1e-6.
  sed "\$a analysis: {tolerance: 1e-6}" "$base.yaml" > "$base-tol1e-6.yaml"
  nice -n 10 "$bin" run -q --no-histories --until 3.6 "$base-tol1e-6.yaml" -o "$base-tol1e-6"
  for k in 1024 2048; do
    dt=$(python3 -c "print(0.005 / $k)")
    sed "\$a analysis: {stepping: fixed, dt: $dt s}" "$base.yaml" > "$base-fixed$k.yaml"
    nice -n 10 "$bin" run -q --no-histories --until 3.6 "$base-fixed$k.yaml" -o "$base-fixed$k"
  done
  echo "theta $a: defaults vs fixed 0.005/1024: $(python3 bench/xy5_window.py "$base-default" "$base-fixed1024")"
  echo "theta $a: tolerance 1e-6 vs fixed 0.005/1024: $(python3 bench/xy5_window.py "$base-tol1e-6" "$base-fixed1024")"
  echo "theta $a: fixed 0.005/1024 vs 0.005/2048: $(python3 bench/xy5_window.py "$base-fixed1024" "$base-fixed2048")"
done
