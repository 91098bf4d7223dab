#!/usr/bin/env bash
# Real-data check of swslam-eval: the reference poses of each corrected CARMEN log (as TUM),
# a perturbed copy of them (rigid offset, 1% scale error, 0.001 rad/pose yaw drift, 1 cm
# noise), and relations derived from the reference poses. Prints ATE, RPE and the relation
# metric per log. Nothing is written outside a temporary directory.
# usage: scripts/check-eval-carmen.sh [BUILD_DIR] [DATASETS_DIR]
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
BUILD="${1:-$HERE/../build}"
DATA="${2:-$HERE/../../shared/datasets}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

for log in "$DATA"/*-corrected.log.gz; do
  name="$(basename "$log" -corrected.log.gz)"
  "$BUILD/apps/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps -i "$log" \
    -o "$TMP/$name.rawlog" --ground-truth "$TMP/$name.tum" > /dev/null
  awk -v seed=1 -v scale=1.01 -v yaw_drift=0.001 -v sigma=0.01 \
    -f "$HERE/perturb-tum.awk" "$TMP/$name.tum" > "$TMP/$name-est.tum"
  awk -v gap=5 -f "$HERE/tum-relations.awk" "$TMP/$name.tum" > "$TMP/$name.relations"
  echo "== $name"
  "$BUILD/apps/swslam-eval" ate "$TMP/$name-est.tum" "$TMP/$name.tum" | grep '^#'
  "$BUILD/apps/swslam-eval" relations "$TMP/$name-est.tum" "$TMP/$name.relations" | grep '^#'
done
