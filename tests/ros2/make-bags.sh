#!/usr/bin/env bash
# ctest fixture ros2_bags: writes the ROS 2 test bags into BIN/tests/ros2-bags/ with writers
# that are not swslam's (make-bags.mjs: the MCAP project's @mcap/core, @foxglove/cdr, the
# sqlite3 program), from the npm packages pinned in package-lock.json:
#   lake-short.bag  the ROS 1 bag swslam-rawlog2bag writes from datasets/lake-short
#   lake-short/     the same messages as ROS 2 bags (read from the ROS 1 bag by @foxglove/rosbag)
#   synthetic/      a 5-scan drive in a room (make-bags.mjs documents its values)
# Usage: make-bags.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1 bin=$2
out=$bin/tests/ros2-bags
for tool in node npm sqlite3; do
  command -v $tool > /dev/null || { echo "ros2 bags: no '$tool' (scripts/install-deps.sh installs it)"; exit 1; }
done
rm -rf "$out"
mkdir -p "$out/npm"
cp "$src/tests/ros2/package.json" "$src/tests/ros2/package-lock.json" "$src/tests/ros2/make-bags.mjs" "$out/npm/"
(cd "$out/npm" && npm ci --no-audit --no-fund --loglevel=error)
"$bin/apps/swslam-rawlog2bag" -i "$src/datasets/lake-short/lake-short.rawlog" -o "$out/lake-short.bag" \
  > "$out/rawlog2bag.log" 2>&1 || { cat "$out/rawlog2bag.log"; exit 1; }
node "$out/npm/make-bags.mjs" "$out/lake-short.bag" "$out/lake-short"
node "$out/npm/make-bags.mjs" synthetic "$out/synthetic"
