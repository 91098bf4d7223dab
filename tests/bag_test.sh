#!/usr/bin/env bash
# ROS 1 bag input end to end: lake-short converted to a bag (swslam-rawlog2bag) gives swslam
# the same trajectory as the rawlog (ATE against ground truth); the bag's errors are named
# with their exit codes: an unknown topic, topics for a rawlog, a truncated bag (1, nothing
# written), a damaged message in the middle (2, the outputs of the scans before it), record
# lengths past the bytes left and a flipped bit in the file header (below).
# swslam-regen-map and swslam-eval consistency read the bag as well.
set -uo pipefail
src=$1 bin=$2/apps
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
log=$src/datasets/lake-short/lake-short.rawlog
gt=$src/datasets/lake-short/lake-short.gt.tum
cfg=$src/config/default.ini
bag=$tmp/lake-short.bag

"$bin/swslam-rawlog2bag" -i "$log" -o "$bag" > "$tmp/convert.log" 2>&1 ||
  { echo "FAIL: swslam-rawlog2bag exited $?"; cat "$tmp/convert.log"; exit 1; }
grep -q "scans: 2461 of sensor 'LIDAR' on /scan" "$tmp/convert.log" || { echo "FAIL: conversion"; cat "$tmp/convert.log"; fail=1; }
grep -q "odometry: 2461 on /odom" "$tmp/convert.log" || { echo "FAIL: odometry conversion"; fail=1; }

run() {  # run NAME INPUT [options...]: swslam's exit code
  local name=$1 input=$2
  shift 2
  "$bin/swslam" -c "$cfg" -i "$input" -o "$tmp/$name" -d -q --no-render "$@" > "$tmp/$name.log" 2>&1
}
ate() { "$bin/swslam-eval" ate "$1" "$gt" | sed -n 's/^ate_rmse=//p'; }

run rawlog "$log" || { echo "FAIL: swslam on the rawlog exited $?"; cat "$tmp/rawlog.log"; exit 1; }
run bag "$bag" || { echo "FAIL: swslam on the bag exited $?"; cat "$tmp/bag.log"; exit 1; }
grep -q "swslam on ROS bag $bag (scans /scan, sensor pose /tf_static 'base_link' -> 'LIDAR', odometry /odom)" "$tmp/bag.log" ||
  { echo "FAIL: the run does not say what it read"; grep "swslam on" "$tmp/bag.log"; fail=1; }
ate_rawlog=$(ate "$tmp/rawlog/trajectory.tum")
ate_bag=$(ate "$tmp/bag/trajectory.tum")
echo "ATE rmse: rawlog $ate_rawlog m, bag $ate_bag m"
awk -v r="$ate_rawlog" -v b="$ate_bag" 'BEGIN { exit !(r != "" && b != "" && b <= r + 0.001 && b < 0.05) }' ||
  { echo "FAIL: the bag run's ATE $ate_bag m is worse than the rawlog's $ate_rawlog m"; fail=1; }
[[ $(grep -vc '^#' "$tmp/bag/trajectory.tum") -eq 2461 ]] || { echo "FAIL: the bag run has not 2461 poses"; fail=1; }

# swslam-regen-map on the bag run, from the bag.
"$bin/swslam-regen-map" -r "$tmp/bag" -i "$bag" -c "$cfg" -o "$tmp/regen" --no-render > "$tmp/regen.log" 2>&1 ||
  { echo "FAIL: swslam-regen-map on the bag exited $?"; cat "$tmp/regen.log"; fail=1; }
[[ -s $tmp/regen/map.png ]] || { echo "FAIL: regen wrote no map.png"; fail=1; }

# swslam-eval consistency: the bag's scans (picked by their label, the topic) agree at the
# trajectory's poses as the rawlog's do.
consistency() { "$bin/swslam-eval" consistency "$tmp/bag/trajectory.tum" "$1" -c "$cfg" --stride 20 "${@:2}" 2>&1 | tail -1; }
c_rawlog=$(consistency "$log")
c_bag=$(consistency "$bag" --sensor-label /scan)
[[ -n $c_bag && $c_bag == "$c_rawlog" ]] || { echo "FAIL: consistency on the bag: '$c_bag', on the rawlog: '$c_rawlog'"; fail=1; }

expect() {  # expect NAME CODE TEXT: the run NAME exited CODE and said TEXT
  local name=$1 want=$2 text=$3 code=$4
  [[ $code -eq $want ]] || { echo "FAIL: $name: exit $code (expected $want)"; cat "$tmp/$name.log"; fail=1; }
  grep -qF -- "$text" "$tmp/$name.log" || { echo "FAIL: $name: no '$text' in:"; cat "$tmp/$name.log"; fail=1; }
}
run unknown "$bag" --scan-topic /front/scan
expect unknown 1 "has no topic '/front/scan'; its topics: /odom (nav_msgs/Odometry, 2461 messages), /scan (sensor_msgs/LaserScan, 2461 messages), /tf_static (tf2_msgs/TFMessage, 1 message)" $?
run wrongtype "$bag" --odom-topic /scan
expect wrongtype 1 "topic '/scan' is sensor_msgs/LaserScan, not nav_msgs/Odometry" $?
run rawlogtopic "$log" --scan-topic /scan
expect rawlogtopic 1 "is not a ROS bag: scan and odometry topics apply only to bags" $?
[[ ! -e $tmp/unknown/trajectory.tum ]] || { echo "FAIL: outputs written for an unknown topic"; fail=1; }

head -c $(($(stat -c %s "$bag") * 2 / 3)) "$bag" > "$tmp/truncated.bag"
run truncated "$tmp/truncated.bag"
expect truncated 1 "rosbag reindex" $?
[[ ! -e $tmp/truncated/trajectory.tum ]] || { echo "FAIL: outputs written for a truncated bag"; fail=1; }

# Scan 1000 states 2^30 + 1 rays: the reading stops there, the outputs hold scans 0-999.
/usr/bin/python3 - "$bag" "$tmp/damaged.bag" <<'PY'
import struct, sys
data = bytearray(open(sys.argv[1], 'rb').read())
# A LaserScan's range_min (0), range_max (30 m), then its ray count (1081).
key = struct.pack('<ffI', 0.0, 30.0, 1081)
at = -1
for _ in range(1001):
    at = data.index(key, at + 1)
data[at + 8:at + 12] = struct.pack('<I', 2**30 + 1)
open(sys.argv[2], 'wb').write(data)
PY
run damaged "$tmp/damaged.bag"
expect damaged 2 "input stopped after 1000 scans: bag '$tmp/damaged.bag': message #" $?
grep -q "runs past the message's" "$tmp/damaged.log" || { echo "FAIL: the damage is not said"; fail=1; }
[[ $(grep -vc '^#' "$tmp/damaged/trajectory.tum" 2>/dev/null) -eq 1000 ]] ||
  { echo "FAIL: the damaged run's trajectory does not hold the 1000 scans before the damage"; fail=1; }

# Damage librosbag trusted (it asserted in rosbag::Buffer::ensureCapacity, exit 134, nothing
# written), in bz2 and lz4 bags: chunk 10 claims 0xFFFFFFF0 bytes uncompressed (the reading
# stops before it, the outputs hold the scans before it) or of data (nothing read: a bag whose
# record lengths disagree with its bytes is not opened); a flipped bit in a field length of
# the file header is named as damage, without the library's "invalid TCPROS header" line.
damage() {  # damage IN OUT WHAT: a chunk's size or data length, or the file header's first field length
  /usr/bin/python3 - "$@" <<'PY'
import struct, sys
src, dst, what = sys.argv[1:]
data = bytearray(open(src, 'rb').read())
u32 = lambda at: struct.unpack_from('<I', data, at)[0]
if what == 'header':
    data[13 + 4 + 1] ^= 0x40  # the file header's first field: 4 bytes of length, a bit of its second byte
else:
    pos, chunks = 13 + 8 + u32(13) + u32(13 + 4 + u32(13)), []
    index_pos = struct.unpack_from('<Q', data, data.index(b'index_pos=') + 10)[0]
    while pos < index_pos:
        header = bytes(data[pos + 4:pos + 4 + u32(pos)])
        if b'op=\x05' in header:
            chunks.append(pos)
        pos += 8 + u32(pos) + u32(pos + 4 + u32(pos))
    chunk = chunks[9]
    at = chunk + 4 + u32(chunk) if what == 'data' else data.index(b'size=', chunk) + 5
    struct.pack_into('<I', data, at, 0xFFFFFFF0)
open(dst, 'wb').write(data)
PY
}
for c in bz2 lz4; do
  "$bin/swslam-rawlog2bag" -i "$log" -o "$tmp/$c.bag" --compression $c > /dev/null 2>&1 || { echo "FAIL: $c bag"; fail=1; }
  damage "$tmp/$c.bag" "$tmp/size_$c.bag" size
  run size_$c "$tmp/size_$c.bag"
  expect size_$c 2 "the bag is damaged: chunk 10 of " $?
  grep -qF "it states 4294967280 bytes uncompressed, more than the 268435456 a chunk may hold" "$tmp/size_$c.log" ||
    { echo "FAIL: size_$c: the chunk's size is not named"; fail=1; }
  n=$(sed -n 's/.*input stopped after \([0-9]*\) scans.*/\1/p' "$tmp/size_$c.log" | head -1)
  [[ -n $n && $n -gt 0 && $(grep -vc '^#' "$tmp/size_$c/trajectory.tum" 2>/dev/null) -eq $n ]] ||
    { echo "FAIL: size_$c: the trajectory does not hold the $n scans before the damaged chunk"; fail=1; }
  damage "$tmp/$c.bag" "$tmp/data_$c.bag" data
  run data_$c "$tmp/data_$c.bag"
  expect data_$c 1 "(a chunk): its data states 4294967280 bytes, but " $?
  grep -qF "is damaged: the record at byte " "$tmp/data_$c.log" || { echo "FAIL: data_$c: no record named"; fail=1; }
  [[ ! -e $tmp/data_$c/trajectory.tum ]] || { echo "FAIL: outputs written for data_$c"; fail=1; }
done
damage "$bag" "$tmp/flipped.bag" header
run flipped "$tmp/flipped.bag"
expect flipped 1 "is damaged: its file header (the record at byte 13): a field of its header states " $?
grep -qF "(a damaged header)" "$tmp/flipped.log" || { echo "FAIL: flipped: the damaged header is not named"; fail=1; }
grep -q "TCPROS\\|truncated" "$tmp/flipped.log" && { echo "FAIL: flipped: a library line or truncation said"; cat "$tmp/flipped.log"; fail=1; }
[[ ! -e $tmp/flipped/trajectory.tum ]] || { echo "FAIL: outputs written for a flipped bit"; fail=1; }

[[ $fail -eq 0 ]] && echo "bag_test: OK"
exit $fail
