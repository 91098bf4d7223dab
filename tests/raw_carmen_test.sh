#!/usr/bin/env bash
# A raw CARMEN log (odometry in the FLASER odom_x odom_y odom_theta fields, no ODOM line):
# tests/data/raw-room.clf.gz (see tests/data/README.md). The converter turns those fields into
# odometry (and says so), the rawlog carries exactly them, --laser-only drops them, and swslam
# runs on it with that odometry, converted or read directly.
# Args: SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1
bin=$2/apps
log=$src/tests/data/raw-room.clf.gz
ref=$src/tests/data/raw-room.tum
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL raw_carmen_test: $*" >&2; exit 1; }

"$bin/swslam-carmen2rawlog" -q -i "$log" -o "$dir/odo.rawlog" > "$dir/odo.txt" || fail "conversion failed"
grep -q "^odometry: 100 (from the FLASER/RLASER odom_x odom_y odom_theta fields: the log has no ODOM lines)" \
  "$dir/odo.txt" || fail "summary: $(grep odometry "$dir/odo.txt")"
"$bin/swslam-carmen2rawlog" -q --laser-only -i "$log" -o "$dir/laser.rawlog" > "$dir/laser.txt" ||
  fail "laser-only conversion failed"
grep -q "^odometry: 0 (100 laser-line odometry readings dropped: laser only)" "$dir/laser.txt" ||
  fail "laser-only summary: $(grep odometry "$dir/laser.txt")"

# The rawlog's odometry is the log's odom_* fields, reading by reading, at the scans' times.
if command -v rawlog-edit > /dev/null; then
  (cd "$dir" && rawlog-edit --export-odometry-txt -i odo.rawlog > /dev/null 2>&1) || fail "rawlog-edit cannot read"
  zcat "$log" | awk '$1 == "FLASER" { n = $2; print $(n + 9), $(n + 6), $(n + 7), $(n + 8) }' > "$dir/fields.txt"
  grep -v '^%' "$dir/odo_ODOM.txt" | awk '{ print $1, $2, $3, $4 }' > "$dir/exported.txt"
  [ "$(wc -l < "$dir/exported.txt")" = 100 ] || fail "$(wc -l < "$dir/exported.txt") odometry readings in the rawlog"
  paste -d' ' "$dir/fields.txt" "$dir/exported.txt" | awk '
    function off(a, b) { d = a - b; return d < 0 ? -d : d }
    { for (i = 1; i <= 4; i++) if (off($i, $(i + 4)) > 1e-4) { print "line " NR ": " $0; bad = 1; exit } }
    END { exit bad }' || fail "the rawlog's odometry is not the log's"
  (cd "$dir" && rawlog-edit --info -i laser.rawlog > info.txt 2>&1) || fail "rawlog-edit cannot read"
  if grep -q "ODOM" "$dir/info.txt"; then fail "odometry left with --laser-only"; fi
fi

# swslam with that odometry, on the converted rawlog and on the log itself: the same run.
run() {
  local name=$1 input=$2
  shift 2
  "$bin/swslam" -c "$src/config/default.ini" -i "$input" -g "$ref" -o "$dir/$name" -d -q --no-render "$@" \
    > "$dir/$name.txt" 2>&1 || fail "swslam on $name: $(tail -3 "$dir/$name.txt")"
  awk -F'|' '/ATE \(rmse\)/ { split($3, v, " "); print v[1] }' "$dir/$name.txt"
}
ate=$(run rawlog "$dir/odo.rawlog")
direct=$(run direct "$log")
echo "ATE with the FLASER odometry: rawlog $ate m, CARMEN log read directly $direct m"
grep -q "odometry: the laser lines' odom_x odom_y odom_theta" "$dir/direct.txt" || fail "swslam does not say where the odometry came from"
[ "$ate" = "$direct" ] || fail "the converted and the direct runs differ: $ate m and $direct m"
awk -v a="$ate" 'BEGIN { exit !(a < 0.05) }' || fail "ATE $ate m"
# The odometry was used: the laser-only conversion, and --no-odometry, give another run.
laser=$(run laser "$dir/laser.rawlog")
ignored=$(run ignored "$dir/odo.rawlog" --no-odometry)
echo "ATE laser only: $laser m; odometry ignored (--no-odometry): $ignored m"
[ "$laser" = "$ignored" ] || fail "--laser-only ($laser m) and --no-odometry ($ignored m) differ"
[ "$laser" != "$ate" ] || fail "the odometry changed nothing ($ate m either way)"
