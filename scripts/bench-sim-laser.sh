#!/usr/bin/env bash
# A simulated scenario run laser only, deterministic, with config/default.ini, scored against
# its ground truth (scripts/bench-campus.sh and scripts/bench-building.sh say what each shows).
# Prints the run's size and loops, its ATE (rmse and largest), the per-scan steps off the truth
# by more than 0.3 m (scripts/odometry-steps.py with the ground truth), and what the scans
# support: their own optimum started at the ground truth (swslam-eval laser-optimum), its
# distance from it, and their optimum started at the run's own result, its distance from the
# run and from the truth.
# Usage: scripts/bench-sim-laser.sh NAME [OUT_DIR]   (datasets/scenarios/NAME.ini; default
#        OUT_DIR out/bench-NAME; generates datasets/NAME/ if missing; needs a build:
#        scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
name=${1:?usage: scripts/bench-sim-laser.sh NAME [OUT_DIR]}
out=${2:-out/bench-$name}
bin=build/apps
[[ -x $bin/swslam && -x $bin/swslam-sim && -x $bin/swslam-eval ]] ||
  { echo "bench-sim-laser: build first (scripts/build.sh)" >&2; exit 1; }
[[ -f datasets/scenarios/$name.ini ]] || { echo "bench-sim-laser: no scenario datasets/scenarios/$name.ini" >&2; exit 1; }
data=datasets/$name
if [[ ! -f $data/$name.rawlog || ! -f $data/$name.gt.tum ]]; then
  "$bin/swslam-sim" --quiet --scenario "datasets/scenarios/$name.ini" --output "$data"
fi
mkdir -p "$out"
rm -rf "${out:?}/run"
"$bin/swslam" -c config/default.ini -i "$data/$name.rawlog" -g "$data/$name.gt.tum" -o "$out/run" \
  -d -q --no-odometry --no-render > /dev/null 2>&1 ||
  { echo "bench-sim-laser: swslam failed (see: $bin/swslam -i $data/$name.rawlog -o $out/run -d --no-odometry)" >&2; exit 1; }
field() { grep -F "| $1" "$2" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }
s=$out/run/summary.md
echo "$name, laser only: $(field 'Number of graph nodes' "$s") nodes, constraints (loops) $(field 'Number of graph constraints' "$s"),"\
  "$(field 'Sensor time / processing time' "$s" | sed 's/.*(//; s/)//')"
"$bin/swslam-eval" ate "$out/run/trajectory.tum" "$data/$name.gt.tum" | grep '^# ATE'
echo "per-scan steps against the truth (scan index, error in m, over 0.3 m):"
python3 scripts/odometry-steps.py "$out/run/trajectory.tum" "$data/$name.gt.tum" --list --max-error 0.3
echo "what the scans support (their own optimum from the ground truth):"
"$bin/swslam-eval" laser-optimum "$data/$name.gt.tum" "$data/$name.rawlog" -c config/default.ini | tail -1
# A run far from the truth whose own result the scans hold as well is in a wrong basin that
# the scans do not contradict: its decisions, not its matching, are what the truth needs.
echo "what the scans support around the run's own result (their optimum from it, and its ATE):"
"$bin/swslam-eval" laser-optimum "$out/run/trajectory.tum" "$data/$name.rawlog" -c config/default.ini \
  -o "$out/run-optimum.tum" | tail -1
"$bin/swslam-eval" ate "$out/run-optimum.tum" "$data/$name.gt.tum" | grep '^# ATE'
