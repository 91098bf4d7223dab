#!/usr/bin/env bash
# How fast each program starts: per program of BUILD_DIR/apps, the shared libraries its
# --help loads (the dynamic loader's report, LD_DEBUG=files) and the wall time of --help, the
# median and the smallest of RUNS runs (a heavy program loads its libraries only after
# parsing: apps/CMakeLists.txt; tests/startup_test.sh checks which are loaded, this prints
# how long it takes).
# Usage: scripts/bench-startup.sh [BUILD_DIR]   (default build). Environment: RUNS (20).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build}/apps
runs=${RUNS:-20}
[[ $runs =~ ^[0-9]+$ && $runs -gt 0 ]] || { echo "bench-startup: RUNS must be a positive integer" >&2; exit 2; }
[[ -x $bin/swslam ]] || { echo "bench-startup: no programs in $bin (scripts/build.sh)" >&2; exit 2; }

printf '%-24s %10s %12s %10s\n' program libraries median_ms min_ms
for app in "$bin"/swslam "$bin"/swslam-*; do
  [[ -f $app && -x $app ]] || continue
  libs=$(LD_DEBUG=files "$app" --help 2>&1 > /dev/null | grep -c 'generating link map' || true)
  times=()
  for ((i = 0; i < runs; i++)); do
    start=$EPOCHREALTIME
    "$app" --help > /dev/null 2>&1
    end=$EPOCHREALTIME
    times+=("$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", (b - a) * 1000 }')")
  done
  sorted=$(printf '%s\n' "${times[@]}" | sort -n)
  printf '%-24s %10d %12s %10s\n' "$(basename "$app")" "$libs" \
    "$(sed -n "$(((runs + 1) / 2))p" <<< "$sorted")" "$(head -1 <<< "$sorted")"
done
