#!/usr/bin/env bash
# The simulated campus (datasets/scenarios/campus.ini: 1.95 km among sparse trees, a figure
# eight whose crossing comes back after some 800 m, then its first 300 m driven again; 180
# rays, 80 m, scans 1 m apart), laser only, deterministic, with config/default.ini: how far
# tracking drifts where no loop is near, and whether the revisits are found.
# Prints the run's size and loops, its ATE against the ground truth (rmse and largest), the
# per-scan steps off the truth by more than 0.3 m
# (scripts/odometry-steps.py with the ground truth), and what the scans support: their own
# optimum started at the ground truth (swslam-eval laser-optimum), its distance from it.
# Usage: scripts/bench-campus.sh [OUT_DIR]   (default out/bench-campus; generates
#        datasets/campus/ if missing; needs a build: scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/bench-campus}
bin=build/apps
[[ -x $bin/swslam && -x $bin/swslam-sim && -x $bin/swslam-eval ]] ||
  { echo "bench-campus: build first (scripts/build.sh)" >&2; exit 1; }
data=datasets/campus
if [[ ! -f $data/campus.rawlog || ! -f $data/campus.gt.tum ]]; then
  "$bin/swslam-sim" --quiet --scenario datasets/scenarios/campus.ini --output "$data"
fi
mkdir -p "$out"
rm -rf "${out:?}/run"
"$bin/swslam" -c config/default.ini -i "$data/campus.rawlog" -g "$data/campus.gt.tum" -o "$out/run" \
  -d -q --no-odometry --no-render > /dev/null 2>&1 ||
  { echo "bench-campus: swslam failed (see: $bin/swslam -i $data/campus.rawlog -o $out/run -d --no-odometry)" >&2; exit 1; }
field() { grep -F "| $1" "$2" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }
s=$out/run/summary.md
echo "campus, laser only: $(field 'Number of graph nodes' "$s") nodes, constraints (loops) $(field 'Number of graph constraints' "$s"),"\
  "$(field 'Sensor time / processing time' "$s" | sed 's/.*(//; s/)//')"
"$bin/swslam-eval" ate "$out/run/trajectory.tum" "$data/campus.gt.tum" | grep '^# ATE'
echo "per-scan steps against the truth (scan index, error in m, over 0.3 m):"
python3 scripts/odometry-steps.py "$out/run/trajectory.tum" "$data/campus.gt.tum" --list --max-error 0.3
echo "what the scans support (their own optimum from the ground truth):"
"$bin/swslam-eval" laser-optimum "$data/campus.gt.tum" "$data/campus.rawlog" -c config/default.ini | tail -1
