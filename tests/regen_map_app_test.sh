#!/usr/bin/env bash
# swslam-regen-map on a short run of lake-short: the map comes back from graph.graph and
# keyframes.tum, with the input and config named on the command line or taken from run.ini; a stats.csv that does not match the trajectory is reported (the pictures then
# mark no scan), a malformed graph.graph line is reported (it was skipped silently), and a
# malformed keyframes.tum line is an error naming the file and line.
set -uo pipefail
src=$1 bin=$2/apps
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
log=$src/datasets/lake-short/lake-short.rawlog
"$bin/swslam" -c "$src/config/default.ini" -i "$log" -o "$tmp/run" -d -q --no-render --max-scans 80 \
  > "$tmp/run.log" 2>&1 || { echo "FAIL: swslam exited $?"; cat "$tmp/run.log"; exit 1; }

regen() { "$bin/swslam-regen-map" -r "$tmp/run" -i "$log" -c "$src/config/default.ini" -o "$tmp/$1" --no-render; }
regen clean > "$tmp/clean.log" 2>&1 || { echo "FAIL: clean regen exited $?"; cat "$tmp/clean.log"; fail=1; }
[[ -s $tmp/clean/map.png ]] || { echo "FAIL: clean regen wrote no map.png"; fail=1; }

# With neither -i nor -c: both from the run's run.ini, the same map; a run folder without
# run.ini (from before it was written) and no -i: an error asking for it, nothing written.
"$bin/swslam-regen-map" -r "$tmp/run" -o "$tmp/recorded" --no-render > "$tmp/recorded.log" 2>&1 ||
  { echo "FAIL: regen from run.ini exited $?"; cat "$tmp/recorded.log"; fail=1; }
cmp -s "$tmp/clean/map.gridmap.gz" "$tmp/recorded/map.gridmap.gz" ||
  { echo "FAIL: the map from run.ini differs from the map with -i and -c"; fail=1; }
cp -r "$tmp/run" "$tmp/old-run" && rm "$tmp/old-run/run.ini"
"$bin/swslam-regen-map" -r "$tmp/old-run" -o "$tmp/old" --no-render > "$tmp/old.log" 2>&1
code=$?
[[ $code -eq 1 ]] || { echo "FAIL: a run without run.ini and no -i: exit $code (expected 1)"; fail=1; }
grep -q "run.ini' is missing.*give the log with -i" "$tmp/old.log" || { echo "FAIL: no message asking for -i"; cat "$tmp/old.log"; fail=1; }
[[ -e $tmp/old ]] && { echo "FAIL: a run without run.ini wrote a map"; fail=1; }

# A --resolution out of the range [map] resolution allows: an error naming it, nothing written.
"$bin/swslam-regen-map" -r "$tmp/run" -i "$log" -c "$src/config/default.ini" -o "$tmp/res" --no-render \
  --resolution 1e9 > "$tmp/res.log" 2>&1
code=$?
[[ $code -eq 1 ]] || { echo "FAIL: --resolution 1e9: exit $code (expected 1)"; fail=1; }
grep -q "resolution must be in \[0.005, 10\] m" "$tmp/res.log" || { echo "FAIL: --resolution 1e9 not named"; cat "$tmp/res.log"; fail=1; }
[[ -e $tmp/res/map.png ]] && { echo "FAIL: --resolution 1e9 wrote a map"; fail=1; }

# A stats.csv that lost its last row no longer matches the trajectory: said, and the pictures
# are drawn without marks.
sed -i '$d' "$tmp/run/stats.csv"
regen short-stats > "$tmp/stats.log" 2>&1 || { echo "FAIL: regen with a short stats.csv exited $?"; cat "$tmp/stats.log"; fail=1; }
grep -q "stats.csv' has 79 rows for a trajectory of 80 poses" "$tmp/stats.log" ||
  { echo "FAIL: the short stats.csv was not reported"; cat "$tmp/stats.log"; fail=1; }
[[ -s $tmp/short-stats/map.png ]] || { echo "FAIL: no map.png with a short stats.csv"; fail=1; }
grep -q "stats.csv" "$tmp/clean.log" && { echo "FAIL: the run's own stats.csv was reported"; cat "$tmp/clean.log"; fail=1; }

# An edge line with a word for a number: skipped, and said.
line=$(grep -n '^EDGE_SE2' "$tmp/run/graph.graph" | head -1 | cut -d: -f1)
sed -i "${line}s/^EDGE_SE2 \([0-9]*\) \([0-9]*\) [^ ]*/EDGE_SE2 \1 \2 abc/" "$tmp/run/graph.graph"
regen edge > "$tmp/edge.log" 2>&1 || { echo "FAIL: regen with a bad edge line exited $?"; cat "$tmp/edge.log"; fail=1; }
grep -q "graph.graph line $line skipped: malformed EDGE_SE2 line" "$tmp/edge.log" ||
  { echo "FAIL: the skipped graph.graph line $line was not reported"; cat "$tmp/edge.log"; fail=1; }

# A keyframe line cut short: an error naming the file and the line, exit 1.
sed -i '3s/ [^ ]*$//' "$tmp/run/keyframes.tum"
regen kf > "$tmp/kf.log" 2>&1
code=$?
[[ $code -eq 1 ]] || { echo "FAIL: bad keyframes.tum: exit $code (expected 1)"; fail=1; }
grep -q "keyframes.tum' line 3" "$tmp/kf.log" || { echo "FAIL: no message naming keyframes.tum line 3"; cat "$tmp/kf.log"; fail=1; }
exit $fail
