#!/usr/bin/env bash
# ctest fixture ros2_bags: writes the ROS 2 test bags into BIN/tests/ros2-bags/ with writers
# that are not swslam's (make-bags.mjs: the MCAP project's @mcap/core, @foxglove/cdr, the
# sqlite3 program), from the npm packages pinned in package-lock.json:
#   lake-short.bag  the ROS 1 bag swslam-rawlog2bag writes from datasets/lake-short
#   lake-short/     the same messages as ROS 2 bags (read from the ROS 1 bag by @foxglove/rosbag)
#   synthetic/      a 5-scan drive in a room (make-bags.mjs documents its values)
#   ours/           ROS 2 bags written by swslam-rawlog2bag (lake-short as a rosbag2 folder and
#                   as a single .mcap; the CARMEN log tests/data/raw-room.clf.gz as a rosbag2
#                   folder), each read back by check-ours.mjs (@mcap/core's indexed reader,
#                   @foxglove/cdr) against the ROS 1 bag of the same log; and raw-room's ROS 1
#                   bag written again by the npm writers (carmen/)
# Usage: make-bags.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1 bin=$2
out=$bin/tests/ros2-bags
for tool in node npm sqlite3; do
  command -v $tool > /dev/null || { echo "ros2 bags: no '$tool' (scripts/install-deps.sh installs it)"; exit 1; }
done
rm -rf "$out"
mkdir -p "$out/npm"
cp "$src/tests/ros2/package.json" "$src/tests/ros2/package-lock.json" "$src/tests/ros2/make-bags.mjs" \
  "$src/tests/ros2/check-ours.mjs" "$out/npm/"
(cd "$out/npm" && npm ci --no-audit --no-fund --loglevel=error)
"$bin/apps/swslam-rawlog2bag" -i "$src/datasets/lake-short/lake-short.rawlog" -o "$out/lake-short.bag" \
  > "$out/rawlog2bag.log" 2>&1 || { cat "$out/rawlog2bag.log"; exit 1; }
node "$out/npm/make-bags.mjs" "$out/lake-short.bag" "$out/lake-short"
node "$out/npm/make-bags.mjs" synthetic "$out/synthetic"

# Ours, checked by the independent readers; a CARMEN log through swslam-carmen2rawlog first.
"$bin/apps/swslam-carmen2rawlog" -i "$src/tests/data/raw-room.clf.gz" -o "$out/raw-room.rawlog" -q \
  > "$out/carmen2rawlog.log" 2>&1 || { cat "$out/carmen2rawlog.log"; exit 1; }
mkdir -p "$out/ours"
for spec in "lake-short.rawlog:lake-short" "lake-short.rawlog:lake-short.mcap" "raw-room.rawlog:raw-room"; do
  in=${spec%%:*} name=${spec#*:}
  [[ $in == lake-short.rawlog ]] && in=$src/datasets/lake-short/$in || in=$out/$in
  "$bin/apps/swslam-rawlog2bag" -i "$in" -o "$out/ours/$name" > "$out/rawlog2bag-$name.log" 2>&1 ||
    { cat "$out/rawlog2bag-$name.log"; exit 1; }
done
"$bin/apps/swslam-rawlog2bag" -i "$out/raw-room.rawlog" -o "$out/raw-room.bag" > "$out/rawlog2bag-raw-room.log" 2>&1 ||
  { cat "$out/rawlog2bag-raw-room.log"; exit 1; }
node "$out/npm/check-ours.mjs" "$out/ours/lake-short" "$out/lake-short.bag"
node "$out/npm/check-ours.mjs" "$out/ours/lake-short.mcap" "$out/lake-short.bag"
node "$out/npm/check-ours.mjs" "$out/ours/raw-room" "$out/raw-room.bag"
node "$out/npm/make-bags.mjs" "$out/raw-room.bag" "$out/carmen"
