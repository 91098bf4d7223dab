#!/usr/bin/env bash
# The odometry of raw CARMEN logs (FLASER odom_* fields, no ODOM line; doc/carmen.md): the
# relations error (swslam-eval relations; relations 5 scans apart derived from the reference
# with scripts/tum-relations.awk) and the ATE of swslam with that odometry against laser only.
# Logs, written by scripts/raw-carmen.py (seed 1): the simulated room (300 scans, 3.4 laps),
# and the FLASER scans of each corrected log in CARMEN_DIR with a generated drifting odometry.
# Usage: scripts/bench-raw-odometry.sh [CARMEN_DIR] (default ../shared/datasets); writes
# out/bench-raw-odometry/.
set -euo pipefail
carmen_dir=${1:-../shared/datasets}
bin=build/apps
out=out/bench-raw-odometry
py=/usr/bin/python3
mkdir -p "$out"
logs=(room)
"$py" scripts/raw-carmen.py room "$out/room.clf.gz" "$out/room.tum" --scans 300
for log in "$carmen_dir"/*-corrected.log.gz; do
  [[ -f $log ]] || continue
  name=$(basename "$log" -corrected.log.gz)
  "$py" scripts/raw-carmen.py corrected "$log" "$out/$name.clf.gz" "$out/$name.tum"
  logs+=("$name")
done
field() { awk -F'|' -v k="$1" 'index($2, k) { gsub(/ /, "", $3); print $3 }' "$2"; }
printf "%-18s %-10s %8s %22s %20s\n" log odometry ATE "relations trans [m]" "relations rot [deg]"
for name in "${logs[@]}"; do
  awk -v gap=5 -f scripts/tum-relations.awk "$out/$name.tum" > "$out/$name.relations"
  for mode in flaser laser-only; do
    flag=(); [[ $mode == laser-only ]] && flag=(--laser-only)
    "$bin/swslam-carmen2rawlog" -q -w "${flag[@]}" -i "$out/$name.clf.gz" -o "$out/$name-$mode.rawlog" > /dev/null
    rm -rf "$out/$name-$mode"
    "$bin/swslam" -c config/default.ini -i "$out/$name-$mode.rawlog" -g "$out/$name.tum" -o "$out/$name-$mode" \
      -d -q --no-render > /dev/null 2>&1 || true
    rel=$("$bin/swslam-eval" relations "$out/$name-$mode/trajectory.tum" "$out/$name.relations" 2> /dev/null | grep '^#' || true)
    trans=$(sed -n 's/^# translational error \([^ ]* +\/- [^ ]*\) m.*/\1/p' <<< "$rel")
    rot=$(sed -n 's/^# rotational error \([^ ]* +\/- [^ ]*\) deg.*/\1/p' <<< "$rel")
    printf "%-18s %-10s %8s %22s %20s\n" "$name" "$mode" "$(field 'ATE (rmse)' "$out/$name-$mode/summary.md")" "$trans" "$rot"
  done
done
