#!/usr/bin/env bash
# Every app: a bad command line exits non-zero with a message; --help exits 0. A negative
# count is refused with a message naming the option.
set -uo pipefail
bin=$2/apps
fail=0
for app in "$bin"/swslam "$bin"/swslam-*; do
  [[ -x $app ]] || continue
  name=$(basename "$app")
  if "$app" --no-such-flag > /dev/null 2>&1; then
    echo "FAIL: $name --no-such-flag exited 0"; fail=1
  fi
  if ! "$app" --help > /dev/null 2>&1; then
    echo "FAIL: $name --help exited non-zero"; fail=1
  fi
done
# A count given as a negative number is refused, not read as 2^64 minus it.
src=$1
expect_refused() {  # message app args...
  local message=$1 out
  shift
  out=$("$@" 2>&1)
  local code=$?
  if [[ $code -ne 1 || $out != *"$message"* ]]; then
    echo "FAIL: $* exited $code, expected 1 and '$message'; printed: $out"; fail=1
  fi
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
lake=$src/datasets/lake-short/lake-short.rawlog
expect_refused "--throttle-scans must be at least 1, got -3" \
  "$bin/swslam" -c "$src/config/default.ini" -i "$lake" -o "$work/out" -d -q --no-render --throttle-scans -3
expect_refused "--max-scans must be at least 0, got -1" \
  "$bin/swslam" -c "$src/config/default.ini" -i "$lake" -o "$work/out" -d -q --no-render --max-scans -1
expect_refused "--max-scans must be at least 0, got -1" \
  "$bin/swslam-localize" -m "$work" -i "$lake" -o "$work/out" --max-scans -1
expect_refused "--starts must be at least 0, got -5" \
  "$bin/swslam-bench-localize" -m "$work" --map-truth "$work/t.tum" -i "$lake" -t "$work/t.tum" --starts -5
expect_refused "--initial-pose \"1 2\": three finite numbers are needed" \
  "$bin/swslam-localize" -m "$work" -i "$lake" -o "$work/out" --initial-pose "1 2"
[[ -e $work/out ]] && { echo "FAIL: a refused command line made $work/out"; fail=1; }
printf 'VERTEX2 0 0 0 0\nVERTEX2 1 1 0 0\nEDGE2 0 1 1 0 0 1 0 1 1 0 0\n' > "$work/g.graph"
expect_refused "--max-iters must be at least 0, got -1" \
  "$bin/swslam-graph-optimize" -i "$work/g.graph" -o "$work/g.g2o" --max-iters -1
exit $fail
