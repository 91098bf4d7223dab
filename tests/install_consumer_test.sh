#!/usr/bin/env bash
# `make install` into a scratch prefix, then build and run a downstream project that does
# find_package(swslam) and links swslam::slam, and run the installed programs: a light one,
# and heavy ones, which load their lib<program>-run.so from the prefix's lib/swslam/ (RUNPATH).
set -euo pipefail
src=$1 bin=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$bin" --prefix "$work/prefix" > "$work/install.log"
test -f "$work/prefix/lib/cmake/swslam/swslamConfig.cmake" || { echo "no package config installed"; exit 1; }
test -f "$work/prefix/include/swslam/plicp/plicp.h" || { echo "headers not installed"; exit 1; }
test -f "$work/prefix/share/swslam/config/default.ini" || { echo "config not installed"; exit 1; }
# The installed headers have the source's module folders, and nothing but headers.
for dir in "$src"/libslam/swslam/*/; do
  m=$(basename "$dir")
  for h in "$dir"*.h; do
    test -f "$work/prefix/include/swslam/$m/$(basename "$h")" || { echo "not installed: swslam/$m/$(basename "$h")"; exit 1; }
  done
done
if find "$work/prefix/include/swslam" -type f ! -name '*.h' | grep -q .; then
  echo "installed beside the headers:"; find "$work/prefix/include/swslam" -type f ! -name '*.h' | head; exit 1
fi
cmake -S "$src/tests/consumer" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/build" -j 2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }
# In a sanitized build (doc/sanitizers.md) the consumer links the sanitizer runtime but not our
# default options: give it the suppressions of what is not ours (ignored by normal builds).
sup=$src/cmake/sanitizers
LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$sup/lsan.supp} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1:suppressions=$sup/ubsan.supp} \
TSAN_OPTIONS=${TSAN_OPTIONS:-suppressions=$sup/tsan.supp} \
  "$work/build/consumer"

prefix=$work/prefix
for app in swslam swslam-live swslam-eval swslam-regen-map swslam-sim swslam-carmen2rawlog swslam-rawlog2bag \
           swslam-bench-matcher swslam-bench-map; do
  test -f "$prefix/lib/swslam/lib$app-run.so" || { echo "lib/swslam/lib$app-run.so not installed"; exit 1; }
  # (A sanitized build writes it as an old-style RPATH: apps/CMakeLists.txt.)
  runpath=$(readelf -d "$prefix/bin/$app" | sed -nE 's/.*\((RUNPATH|RPATH)\).*\[(.*)\]/\2/p')
  [[ $runpath == '$ORIGIN/../lib/swslam' ]] ||
    { echo "installed $app's RUNPATH is '$runpath', not \$ORIGIN/../lib/swslam"; exit 1; }
done
"$prefix/bin/swslam" --help > /dev/null || { echo "installed swslam --help failed"; exit 1; }
"$prefix/bin/swslam-config" -c "$prefix/share/swslam/config/default.ini" > "$work/config.txt" ||
  { echo "installed swslam-config failed"; exit 1; }
grep -q '^\[tracking\]' "$work/config.txt" || { echo "installed swslam-config printed no [tracking]"; exit 1; }
printf '1 0 0 0 0 0 0 1\n2 1 0 0 0 0 0 1\n' > "$work/t.tum"
"$prefix/bin/swslam-eval" ate "$work/t.tum" "$work/t.tum" > "$work/eval.txt" ||
  { echo "installed swslam-eval failed"; cat "$work/eval.txt"; exit 1; }
grep -q '^ate_rmse=' "$work/eval.txt" || { echo "installed swslam-eval printed no ATE:"; cat "$work/eval.txt"; exit 1; }
echo "installed: the consumer, swslam --help, swslam-config and swslam-eval (lib/swslam/libswslam-eval-run.so) ran"
