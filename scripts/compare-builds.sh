#!/usr/bin/env bash
# Do two builds of swslam give the same outputs? Runs each build's `swslam --deterministic`
# with its own source tree's config/default.ini (a build reads only its own keys) on this
# tree's lake-short and valley (generated from its scenario if
# missing) and compares trajectory.tum, keyframes.tum, graph.graph, map.gridmap.gz and map.pgm
# byte for byte, printing an md5 per file and build. A graph.graph that differs only in the
# " switched_off" marks of the edges the robust kernel distrusts (added after a build) is said
# to be so. Exits 1 if any file differs otherwise.
# Usage: scripts/compare-builds.sh OLD_BUILD_DIR NEW_BUILD_DIR   (e.g. a worktree's build/)
set -euo pipefail
cd "$(dirname "$0")/.."
[[ $# -eq 2 ]] || { echo "usage: $0 OLD_BUILD_DIR NEW_BUILD_DIR" >&2; exit 2; }
old=$(realpath "$1") new=$(realpath "$2")
sourceOf() { sed -n 's/^swslam_SOURCE_DIR:STATIC=//p' "$1/CMakeCache.txt"; }
for b in "$old" "$new"; do
  [[ -x $b/apps/swslam ]] || { echo "compare-builds: no $b/apps/swslam" >&2; exit 2; }
  [[ -f $(sourceOf "$b")/config/default.ini ]] || { echo "compare-builds: no source tree for $b" >&2; exit 2; }
done
[[ -f datasets/valley/valley.rawlog ]] || bash scripts/gen-datasets.sh valley > /dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

status=0
for data in lake-short valley; do
  for side in old new; do
    bin=$old; [[ $side == new ]] && bin=$new
    "$bin/apps/swslam" -c "$(sourceOf "$bin")/config/default.ini" -i "datasets/$data/$data.rawlog" -o "$work/$side-$data" -d -q \
      > /dev/null 2>&1 || { echo "compare-builds: the $side build failed on $data" >&2; exit 1; }
  done
  for f in trajectory.tum keyframes.tum graph.graph map.gridmap.gz map.pgm; do
    a=$work/old-$data/$f b=$work/new-$data/$f
    sums="$(md5sum < "$a" | cut -c1-32) $(md5sum < "$b" | cut -c1-32)"
    if cmp -s "$a" "$b"; then
      echo "$data/$f: identical ($sums)"
    elif [[ $f == graph.graph ]] && cmp -s <(sed 's/ switched_off$//' "$a") <(sed 's/ switched_off$//' "$b"); then
      echo "$data/$f: identical but for $(grep -c ' switched_off$' "$b") switched_off marks ($sums)"
    else
      echo "$data/$f: DIFFERENT ($sums)"
      status=1
    fi
  done
done
exit $status
