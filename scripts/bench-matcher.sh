#!/usr/bin/env bash
# The figures of doc/plicp.md: swslam-bench-matcher on the bundled lake-short dataset
# (1081 rays over 270 deg) and on every corrected CARMEN log found in ../shared/datasets
# (or the folder given), converted laser-only with their reference poses.
# Usage: scripts/bench-matcher.sh [CARMEN_DIR]    (needs a build: scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
carmen_dir=${1:-../shared/datasets}
bin=build/apps
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One core, as the figures are quoted (taskset from util-linux, when present).
pin=()
if command -v taskset > /dev/null; then pin=(taskset -c 0); fi
run() {  # rawlog gt
  "${pin[@]}" "$bin/swslam-bench-matcher" --input "$1" --ground-truth "$2" --config config/default.ini --floor
}
run datasets/lake-short/lake-short.rawlog datasets/lake-short/lake-short.gt.tum
shopt -s nullglob
for log in "$carmen_dir"/*-corrected.log.gz; do
  name=$(basename "$log" -corrected.log.gz)
  "$bin/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps -i "$log" \
    -o "$work/$name.rawlog" --ground-truth "$work/$name.tum" > /dev/null
  run "$work/$name.rawlog" "$work/$name.tum"
done
