#!/usr/bin/env bash
# The UAL campus loop (../shared/datasets/ual-campus-2014-05-23.rawlog: 528 m around a building
# block lined with trees, SICK 361 beams at 18 Hz, wheel odometry; no ground truth) run twice,
# deterministic, with config/default.ini: with its odometry, and laser only (--no-odometry).
# The odometry run closes the loop and its map is crisp, so it is the reference the laser-only
# run is scored against (doc/evaluation.md, "Logs without ground truth"):
# - each run's size, loops and speed (Table I);
# - the laser-only trajectory's ATE against the odometry run's;
# - the loop's end-to-start distance in each run, and the difference;
# - per scan, the laser-only step against the odometry run's (scripts/odometry-steps.py with
#   the odometry run as the reference): median, 95th percentile, and each step over 0.3 m.
#   The log drops eight scans now and then (0.43 s, 1.6 m), and its wheel odometry loses the
#   ticks of the same gaps, so a step over a gap can be the odometry run's error.
# Usage: scripts/bench-ual.sh [RAWLOG] [OUT_DIR]   (defaults
#        ../shared/datasets/ual-campus-2014-05-23.rawlog, out/bench-ual; needs a build:
#        scripts/build.sh). Outputs go to OUT_DIR/odometry/ and OUT_DIR/laser/.
set -euo pipefail
cd "$(dirname "$0")/.."
log=${1:-../shared/datasets/ual-campus-2014-05-23.rawlog}
out=${2:-out/bench-ual}
bin=build/apps
[[ -x $bin/swslam && -x $bin/swslam-eval ]] || { echo "bench-ual: build first (scripts/build.sh)" >&2; exit 1; }
[[ -f $log ]] || { echo "bench-ual: no log $log" >&2; exit 1; }
mkdir -p "$out"
field() { grep -F "| $1" "$2" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }
# The distance from a TUM file's first pose to its last.
end_to_start() { awk '!/^#/ && NF >= 3 { if (!n++) { x0 = $2; y0 = $3 } x = $2; y = $3 }
  END { printf "%.3f", sqrt((x - x0)^2 + (y - y0)^2) }' "$1"; }

echo "| run | nodes | constraints (loops) | real time | end to start |"
echo "|---|---|---|---|---|"
for mode in odometry laser; do
  flags=(-d -q --no-render)
  [[ $mode == laser ]] && flags+=(--no-odometry)
  rm -rf "${out:?}/$mode"
  "$bin/swslam" -c config/default.ini -i "$log" -o "$out/$mode" "${flags[@]}" > /dev/null 2>&1 ||
    { echo "bench-ual: swslam failed (see: $bin/swslam -i $log -o $out/$mode ${flags[*]})" >&2; exit 1; }
  s=$out/$mode/summary.md
  echo "| $mode | $(field 'Number of graph nodes' "$s") | $(field 'Number of graph constraints' "$s") |" \
    "$(field 'Sensor time / processing time' "$s" | sed 's/.*(//; s/)//') | $(end_to_start "$out/$mode/trajectory.tum") m |"
done
echo
echo "laser only against the odometry run:"
"$bin/swslam-eval" ate "$out/laser/trajectory.tum" "$out/odometry/trajectory.tum" | grep '^# ATE'
echo "end-to-start difference: $(awk -v a="$(end_to_start "$out/laser/trajectory.tum")" \
  -v b="$(end_to_start "$out/odometry/trajectory.tum")" 'BEGIN { d = a - b; printf "%.3f", d < 0 ? -d : d }') m"
echo "per-scan steps (scan index, error in m, over 0.3 m):"
python3 scripts/odometry-steps.py "$out/laser/trajectory.tum" "$out/odometry/trajectory.tum" --list --max-error 0.3
