#!/usr/bin/env bash
# ROS 2 bags end to end, written by independent writers (tests/ros2/make-bags.sh, the ctest
# fixture ros2_bags): lake-short as a ROS 1 bag (swslam-rawlog2bag) and as ROS 2 bags of the
# same messages (zstd, lz4, uncompressed and unchunked MCAP, big-endian CDR, .db3, .db3 with
# zstd per message, .db3 compressed whole) give swslam the same trajectory, byte for byte in deterministic mode, and
# say what they read; ROS 2 bags swslam-rawlog2bag wrote, of lake-short and of a CARMEN log, and
# the npm writers' of the CARMEN log give the rawlog's trajectory byte for byte; swslam-eval consistency reads one too. Damaged and foreign ROS 2 inputs
# are named with their exit codes.
set -uo pipefail
src=$1 bin=$2/apps bags=$2/tests/ros2-bags
[[ -d $bags/lake-short ]] || { echo "FAIL: no $bags/lake-short: the fixture ros2_bags_make did not run"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
cfg=$src/config/default.ini

run() {  # run NAME INPUT [options...]: swslam's exit code
  local name=$1 input=$2
  shift 2
  "$bin/swslam" -c "$cfg" -i "$input" -o "$tmp/$name" -d -q --no-render "$@" > "$tmp/$name.log" 2>&1
}
run ros1 "$bags/lake-short.bag" || { echo "FAIL: swslam on the ROS 1 bag exited $?"; cat "$tmp/ros1.log"; exit 1; }
for b in zstd.mcap be.mcap unchunked.mcap lz4 db3 db3-zstd db3-file-zstd; do
  run "$b" "$bags/lake-short/$b" || { echo "FAIL: swslam on $b exited $?"; cat "$tmp/$b.log"; fail=1; continue; }
  grep -qF "swslam on ROS 2 bag $bags/lake-short/$b (scans /scan, sensor pose /tf_static 'base_link' -> 'LIDAR', odometry /odom)" "$tmp/$b.log" ||
    { echo "FAIL: $b: the run does not say what it read"; grep "swslam on" "$tmp/$b.log"; fail=1; }
  if cmp -s "$tmp/ros1/trajectory.tum" "$tmp/$b/trajectory.tum"; then
    echo "$b: the ROS 1 bag's trajectory, byte for byte ($(grep -vc '^#' "$tmp/$b/trajectory.tum") poses)"
  else
    echo "FAIL: $b: its trajectory differs from the ROS 1 bag's"; fail=1
  fi
done

# The figure: lake-short and a CARMEN log (tests/data/raw-room.clf.gz through
# swslam-carmen2rawlog) as ROS 2 bags written both ways, by the npm writers (from the ROS 1 bag)
# and by swslam-rawlog2bag (ours/: a rosbag2 folder, a single .mcap), give the rawlog's
# trajectory byte for byte.
same_as() {  # same_as REFERENCE NAME INPUT: swslam on INPUT gives REFERENCE's trajectory
  local reference=$1 name=$2 input=$3
  run "$name" "$input" || { echo "FAIL: swslam on $input exited $?"; cat "$tmp/$name.log"; fail=1; return; }
  if cmp -s "$tmp/$reference/trajectory.tum" "$tmp/$name/trajectory.tum"; then
    echo "$name: the rawlog's trajectory, byte for byte ($(grep -vc '^#' "$tmp/$name/trajectory.tum") poses)"
  else
    echo "FAIL: $name: its trajectory differs from the rawlog's"; fail=1
  fi
}
run rawlog "$src/datasets/lake-short/lake-short.rawlog" || { echo "FAIL: swslam on lake-short.rawlog"; fail=1; }
same_as rawlog lake-ros1 "$bags/lake-short.bag"
same_as rawlog lake-npm-zstd "$bags/lake-short/zstd.mcap"
same_as rawlog lake-npm-db3 "$bags/lake-short/db3"
same_as rawlog lake-ours "$bags/ours/lake-short"
same_as rawlog lake-ours-mcap "$bags/ours/lake-short.mcap"
run carmen-rawlog "$bags/raw-room.rawlog" || { echo "FAIL: swslam on raw-room.rawlog"; fail=1; }
same_as carmen-rawlog carmen-ros1 "$bags/raw-room.bag"
same_as carmen-rawlog carmen-npm-zstd "$bags/carmen/zstd.mcap"
same_as carmen-rawlog carmen-npm-lz4 "$bags/carmen/lz4"
same_as carmen-rawlog carmen-npm-db3 "$bags/carmen/db3"
same_as carmen-rawlog carmen-ours "$bags/ours/raw-room"

# swslam-eval consistency reads a ROS 2 bag's scans as the ROS 1 bag's.
consistency() { "$bin/swslam-eval" consistency "$tmp/ros1/trajectory.tum" "$1" -c "$cfg" --stride 40 --sensor-label /scan 2>&1 | tail -1; }
c1=$(consistency "$bags/lake-short.bag")
c2=$(consistency "$bags/lake-short/db3")
[[ -n $c2 && $c2 == "$c1" ]] || { echo "FAIL: consistency on the .db3 bag: '$c2', on the ROS 1 bag: '$c1'"; fail=1; }

expect() {  # expect NAME CODE TEXT CODE_GOT: the run NAME exited CODE and said TEXT
  local name=$1 want=$2 text=$3 code=$4
  [[ $code -eq $want ]] || { echo "FAIL: $name: exit $code (expected $want)"; cat "$tmp/$name.log"; fail=1; }
  grep -qF -- "$text" "$tmp/$name.log" || { echo "FAIL: $name: no '$text' in:"; cat "$tmp/$name.log"; fail=1; }
}
run unknown "$bags/lake-short/zstd.mcap" --scan-topic /front/scan
expect unknown 1 "has no topic '/front/scan'; its topics: /odom (nav_msgs/msg/Odometry, 2461 messages), /scan (sensor_msgs/msg/LaserScan, 2461 messages), /tf_static (tf2_msgs/msg/TFMessage, 1 message)" $?
run wrongtype "$bags/lake-short/db3" --odom-topic /scan
expect wrongtype 1 "topic '/scan' is sensor_msgs/msg/LaserScan, not nav_msgs/msg/Odometry" $?

# An MCAP file cut in the middle: the scans before the cut, then exit 2 naming the record.
size=$(stat -c %s "$bags/lake-short/unchunked.mcap")
head -c $((size / 2)) "$bags/lake-short/unchunked.mcap" > "$tmp/cut.mcap"
run cut "$tmp/cut.mcap"
expect cut 2 "cannot be read: MCAP record at byte" $?
grep -q "input stopped after" "$tmp/cut.log" || { echo "FAIL: cut: no 'input stopped after'"; fail=1; }
[[ -s $tmp/cut/trajectory.tum ]] || { echo "FAIL: cut: no trajectory of the scans before the cut"; fail=1; }

# Not an MCAP file; a bag compressed file by file whose file is cut short.
echo "hello" > "$tmp/text.mcap"
run notmcap "$tmp/text.mcap"
expect notmcap 1 "is not an MCAP file: it does not start with its magic" $?
cp -r "$bags/lake-short/db3-file-zstd" "$tmp/filezstd"
truncate -s 100000 "$tmp/filezstd/db3-file-zstd_0.db3.zstd"
run filezstd "$tmp/filezstd"
expect filezstd 1 "db3-file-zstd_0.db3.zstd': its zstd data is cut short (a truncated file)" $?

exit $fail
