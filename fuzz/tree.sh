# Sourced by fuzz/run and fuzz/planted: configures the fuzz targets' tree $build, passing "$@".
# $build is either CI's sanitizer tree (the project configured with clang, the sanitizers and
# -DISOPOUND_BUILD_FUZZ=ON by .ci/run: one build for the test suite and the fuzz targets) or a
# tree of fuzz/ alone (long campaigns; fuzz/CMakeLists.txt).
configure_fuzz_tree() {
  if grep -q '^ISOPOUND_BUILD_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
    cmake -B "$build" "$@" >/dev/null
  else
    cmake -S fuzz -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "$@" >/dev/null
  fi
}
