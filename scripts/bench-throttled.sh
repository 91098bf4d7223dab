#!/usr/bin/env bash
# Larger steps on the same log: MRPT's office rawlog (../shared/datasets, or the folder given),
# laser only, at its full rate and then keeping one scan in N (swslam --throttle-scans N) for
# N = 2..7, as a slower sensor or a log subsampled like the corrected CARMEN logs would give it
# (0.2-0.8 m and up to 20 deg between the scans kept at N = 5). Each run is scored twice:
# - its ATE against the full-rate run's trajectory (the log has no ground truth);
# - each step against the log's odometry (scripts/odometry-steps.py): the steps off by more
#   than 5 cm and 20 cm. At the full rate the 3 steps over 20 cm are scans 926-930, where an
#   object stands 0.5 m in front of the sensor (doc/tracking.md, "Scans kept apart").
# Usage: scripts/bench-throttled.sh [DATASETS_DIR]    (needs a build: scripts/build.sh,
#        rawlog-edit from mrpt-apps and python3)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-../shared/datasets}
office=$dir/driving_in_office_obs.rawlog
bin=build/apps
[[ -f $office ]] || { echo "bench-throttled: no $office" >&2; exit 1; }
command -v rawlog-edit > /dev/null || { echo "bench-throttled: needs rawlog-edit (mrpt-apps)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# rawlog-edit 2.5 writes its export beside its input: run it on a copy in the work folder.
cp "$office" "$work/office.rawlog"
(cd "$work" && rawlog-edit -q -i office.rawlog --export-odometry-txt > /dev/null 2>&1)
pin=()
if command -v taskset > /dev/null; then pin=(taskset -c 0); fi
field() { grep -F "| $1 |" "$2" | awk -F'|' '{gsub(/^ +| +$/, "", $3); print $3}'; }

echo "| one scan in | scans | ATE against the full-rate run | steps against odometry |"
echo "|---|---|---|---|"
for n in 1 2 3 4 5 6 7; do
  out=$work/n$n
  gt=()
  [[ $n -gt 1 ]] && gt=(-g "$work/n1/trajectory.tum")
  if ! "${pin[@]}" "$bin/swslam" -c config/default.ini -i "$office" -o "$out" -d -q --no-render --no-odometry \
       --throttle-scans "$n" "${gt[@]}" > /dev/null 2>&1; then
    echo "| $n | swslam failed: $bin/swslam -c config/default.ini -i $office -o $out -d --no-odometry --throttle-scans $n | | |"
    continue
  fi
  ate=$([[ $n -gt 1 ]] && field 'ATE (rmse)' "$out/summary.md" || echo "(the reference)")
  steps=$(python3 scripts/odometry-steps.py "$out/trajectory.tum" "$work/office_odometry.txt")
  echo "| $n | $(field 'Scans processed (skipped)' "$out/summary.md") | $ate | $steps |"
done
