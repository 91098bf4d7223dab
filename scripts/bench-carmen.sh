#!/usr/bin/env bash
# The corrected CARMEN logs, laser only, with config/default.ini (no per-dataset tuning): each
# log's ATE against its reference poses, graph size, and the scans tracked by fallback and the
# ambiguous ones (doc/tracking.md). Needs a built tree (scripts/build.sh).
# Usage: scripts/bench-carmen.sh [CARMEN_DIR] [OUT_DIR]   (defaults ../shared/datasets,
# out/bench-carmen); swslam's outputs go to OUT_DIR/<log>/.
set -euo pipefail
cd "$(dirname "$0")/.."
carmen_dir=${1:-../shared/datasets}
out=${2:-out/bench-carmen}
bin=build/apps
cfg=config/default.ini
mkdir -p "$out"
field() { grep -F "| $1" "$2" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }
printf "%-20s %-10s %-7s %-24s %-9s %-9s\n" log ATE nodes "constraints (loops)" fallback ambiguous
for log in "$carmen_dir"/*-corrected.log.gz; do
  [[ -f $log ]] || continue
  name=$(basename "$log" -corrected.log.gz)
  rm -rf "${out:?}/$name"  # no stale results
  "$bin/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps -i "$log" -o "$out/$name.rawlog" \
    --ground-truth "$out/$name.gt.tum" > /dev/null 2>&1
  "$bin/swslam" -c $cfg -i "$log" -g "$out/$name.gt.tum" -o "$out/$name" -d -q --no-odometry \
    --no-render > /dev/null 2>&1 || true
  s=$out/$name/summary.md
  if [[ ! -f $s ]]; then echo "$name: swslam failed (see: $bin/swslam -c $cfg -i $log -o $out/$name -d --no-odometry)"; continue; fi
  printf "%-20s %-10s %-7s %-24s %-9s %-9s\n" "$name" "$(field 'ATE (rmse)' "$s")" \
    "$(field 'Number of graph nodes' "$s")" "$(field 'Number of graph constraints' "$s")" \
    "$(field 'Scans tracked by fallback' "$s")" "$(field 'Ambiguous scans' "$s")"
done
