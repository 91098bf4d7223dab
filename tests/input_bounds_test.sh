#!/usr/bin/env bash
# Whole programs on input past the bounds every reader applies (doc/reliability.md): a scan
# whose sensor is mounted far out, a CARMEN log in UTF-16, an output folder whose lock file
# is a folder or a FIFO, and a trajectory scored only in part. Each ends with its named
# error and exit code, or its warning, and nothing half written.
# Before: x = 1e30 corrupted the heap in threaded swslam (exit 134), 1e4 took 20 s and 1.2 GB;
# the UTF-16 log was "no laser scan" (swslam-carmen2rawlog: "cannot write 'out.rawlog'").
# Usage: input_bounds_test.sh SOURCE_DIR BINARY_DIR
set -uo pipefail
src=$1 build=$2
source "$src/tests/python_support.sh"
python=$(find_python gzip)
[[ -n $python ]] || { echo "SKIP: no python3"; exit 77; }
tmp=$(mktemp -d)
trap '[[ -n ${KEEP:-} ]] || rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $name: $*"; fail=1; }
swslam() { timeout 60 "$build/apps/swslam" -c "$src/config/default.ini" -q --no-render "$@"; }

# The first 30 scans of lake-short with every scan's sensor pose moved to x = X (the first
# double after the pose's class name and version in each scan entry).
mounted_at() {
  "$python" - "$src/datasets/lake-short/lake-short.rawlog" "$1" "$2" << 'PY'
import gzip, struct, sys
data = gzip.open(sys.argv[1]).read()
scan = b"\xa2mrpt::obs::CObservation2DRangeScan"
pose = b"\x94mrpt::poses::CPose3D\x03"
end = -1
for _ in range(31):
    end = data.find(scan, end + 1)
out = bytearray(data[:end])
at = 0
while True:
    at = out.find(pose, at)
    if at < 0: break
    struct.pack_into("<d", out, at + len(pose), float(sys.argv[3]))
    at += len(pose)
open(sys.argv[2], "wb").write(out)
PY
}

for x in 1e30 1e4; do
  shown=$(printf '%g' "$x")  # as the message prints it
  mounted_at "$tmp/far.rawlog" "$x"
  for mode in threaded -d; do
    name="mounted at x = $x ($mode)"
    args=(-i "$tmp/far.rawlog" -o "$tmp/out-$x$mode")
    [[ $mode == -d ]] && args+=(-d)
    start=$SECONDS
    swslam "${args[@]}" > "$tmp/out.txt" 2> "$tmp/err.txt"
    code=$?
    ((code == 2)) || bad "exit $code, not 2: $(cat "$tmp/err.txt")"
    grep -q "rawlog '$tmp/far.rawlog': entry #[0-9]* (at byte [0-9]*): scan '.*': sensor mounted at ($shown, .* beyond the 50 m a sensor is mounted" \
      "$tmp/err.txt" || bad "the mounting is not named: $(cat "$tmp/err.txt")"
    grep -q "nothing written" "$tmp/err.txt" || bad "no 'nothing written'"
    [[ -e $tmp/out-$x$mode/trajectory.tum ]] && bad "outputs written"
    ((SECONDS - start < 20)) || bad "took $((SECONDS - start)) s"
  done
done
echo "mounted far: $(head -1 "$tmp/err.txt")"

name="CARMEN log in UTF-16"
printf 'PARAM robot_frontlaser_offset 0.1 nohost 0\nFLASER 3 1.0 1.1 1.2 0 0 0 0 0 0 12.5 host 12.5\n' |
  iconv -f ASCII -t UTF-16 > "$tmp/wide.log"
"$build/apps/swslam-carmen2rawlog" -i "$tmp/wide.log" -o "$tmp/wide.rawlog" > /dev/null 2> "$tmp/err.txt"
code=$?
((code == 1)) || bad "swslam-carmen2rawlog: exit $code, not 1"
grep -q "carmen: '$tmp/wide.log' is UTF-16LE text (it starts with the byte order mark FF FE), not the ASCII of a log: convert it first (iconv -f UTF-16 -t UTF-8)" \
  "$tmp/err.txt" || bad "swslam-carmen2rawlog: $(cat "$tmp/err.txt")"
grep -q "cannot write" "$tmp/err.txt" && bad "swslam-carmen2rawlog blames the output"
[[ -e $tmp/wide.rawlog ]] && bad "a rawlog was written"
swslam -i "$tmp/wide.log" -o "$tmp/out-wide" > /dev/null 2> "$tmp/err.txt"
code=$?
((code == 1)) || bad "swslam: exit $code, not 1"
grep -q "is UTF-16LE text" "$tmp/err.txt" || bad "swslam: $(cat "$tmp/err.txt")"
echo "UTF-16: $(cat "$tmp/err.txt")"

for kind in directory FIFO; do
  name=".swslam.lock a $kind"
  mkdir -p "$tmp/locked-$kind"
  if [[ $kind == directory ]]; then mkdir "$tmp/locked-$kind/.swslam.lock"; else mkfifo "$tmp/locked-$kind/.swslam.lock"; fi
  swslam -i "$src/datasets/lake-short/lake-short.rawlog" --max-scans 5 -o "$tmp/locked-$kind" > /dev/null 2> "$tmp/err.txt"
  code=$?
  ((code == 1)) || bad "exit $code, not 1"
  grep -q "output folder '$tmp/locked-$kind': its lock file .swslam.lock is a $kind, not a file: remove it" \
    "$tmp/err.txt" || bad "$(cat "$tmp/err.txt")"
done
echo "lock: $(cat "$tmp/err.txt")"

name="a trajectory scored in part"
awk '/^#/ { print; next } { if (++n % 3 == 0) $1 = sprintf("%.6f", $1 - 0.5); print }' \
  "$src/datasets/lake-short/lake-short.gt.tum" > "$tmp/back.tum"
"$build/apps/swslam-eval" ate "$tmp/back.tum" "$src/datasets/lake-short/lake-short.gt.tum" > /dev/null 2> "$tmp/err.txt"
code=$?
((code == 0)) || bad "exit $code: $(cat "$tmp/err.txt")"
grep -Eq "swslam-eval: warning: $tmp/back.tum: scored [0-9]+ of the [0-9]+ estimated poses: [0-9]+ have no ground-truth pose within 0.01 s of their stamp \(the estimate's stamps step back" \
  "$tmp/err.txt" || bad "no warning: $(cat "$tmp/err.txt")"
echo "eval: $(cat "$tmp/err.txt")"
exit $fail
