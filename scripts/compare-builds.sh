#!/usr/bin/env bash
# Do two builds of swslam give the same outputs? Runs each build's `swslam --deterministic`
# with its own source tree's config/default.ini (a build reads only its own keys) on this
# tree's lake-short and valley (generated from its scenario if missing), and the runs of
# scripts/bench-carmen.sh (the corrected CARMEN logs forwards, backwards and started
# part-way, laser only) when CARMEN_DIR holds them. It compares trajectory.tum,
# keyframes.tum, graph.graph, map.gridmap.gz and map.pgm of every run byte for byte, printing
# an md5 per file and build. A graph.graph that differs only in the " switched_off" marks of
# the edges the robust kernel distrusts (added after a build) is said to be so. Exits 1 if any
# file differs otherwise.
# Usage: scripts/compare-builds.sh OLD_BUILD_DIR NEW_BUILD_DIR [CARMEN_DIR]
#        (e.g. a worktree's build/; CARMEN_DIR defaults to ../shared/datasets)
set -euo pipefail
cd "$(dirname "$0")/.."
[[ $# -eq 2 || $# -eq 3 ]] || { echo "usage: $0 OLD_BUILD_DIR NEW_BUILD_DIR [CARMEN_DIR]" >&2; exit 2; }
old=$(realpath "$1") new=$(realpath "$2")
carmen_dir=${3:-../shared/datasets}
sourceOf() { sed -n 's/^swslam_SOURCE_DIR:STATIC=//p' "$1/CMakeCache.txt"; }
for b in "$old" "$new"; do
  [[ -x $b/apps/swslam ]] || { echo "compare-builds: no $b/apps/swslam" >&2; exit 2; }
  [[ -f $(sourceOf "$b")/config/default.ini ]] || { echo "compare-builds: no source tree for $b" >&2; exit 2; }
done
[[ -f datasets/valley/valley.rawlog ]] || bash scripts/gen-datasets.sh valley > /dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for side in old new; do
  bin=$old; [[ $side == new ]] && bin=$new
  for data in lake-short valley; do
    "$bin/apps/swslam" -c "$(sourceOf "$bin")/config/default.ini" -i "datasets/$data/$data.rawlog" -o "$work/$side/$data" -d -q \
      > /dev/null 2>&1 || { echo "compare-builds: the $side build failed on $data" >&2; exit 1; }
  done
  if compgen -G "$carmen_dir/*-corrected.log.gz" > /dev/null; then
    SWSLAM_BUILD=$bin bash scripts/bench-carmen.sh "$carmen_dir" "$work/$side/carmen" > /dev/null
  fi
done

status=0
runs=(lake-short valley)
for r in "$work"/old/carmen/*/; do [[ -d $r ]] && runs+=("carmen/$(basename "$r")"); done
for run in "${runs[@]}"; do
  for f in trajectory.tum keyframes.tum graph.graph map.gridmap.gz map.pgm; do
    a=$work/old/$run/$f b=$work/new/$run/$f
    if [[ ! -f $a || ! -f $b ]]; then
      echo "$run/$f: MISSING ($( [[ -f $a ]] && echo new || echo old ))"
      status=1
      continue
    fi
    sums="$(md5sum < "$a" | cut -c1-32) $(md5sum < "$b" | cut -c1-32)"
    if cmp -s "$a" "$b"; then
      echo "$run/$f: identical ($sums)"
    elif [[ $f == graph.graph ]] && cmp -s <(sed 's/ switched_off$//' "$a") <(sed 's/ switched_off$//' "$b"); then
      echo "$run/$f: identical but for $(grep -c ' switched_off$' "$b") switched_off marks ($sums)"
    else
      echo "$run/$f: DIFFERENT ($sums)"
      status=1
    fi
  done
done
echo "compare-builds: ${#runs[@]} runs, $( ((status == 0)) && echo "every file identical" || echo "some files differ")"
exit $status
