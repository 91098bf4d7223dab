#!/usr/bin/env bash
# The valley driven again with other sensor noise (noise_seed 100 + DRAW) and three rocks taken
# away and three put (swslam-sim [changes], seed DRAW), for the change reports of
# bench-long.sh section 3 and bench-localize.sh section 2: writes DIR/changed-DRAW.ini and
# DIR/data-DRAW/ (changed-DRAW.rawlog, its reference poses and changed-DRAW.changes.csv).
# Usage: scripts/changed-valley.sh DRAW DIR   (expects build/ from scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
[[ $# -eq 2 && $1 =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 DRAW DIR  (DRAW a positive whole number)" >&2; exit 2; }
draw=$1 dir=$2
awk -v d="$draw" '/^noise_seed/ { next } { print } /^seed *=/ { print "noise_seed = " 100 + d }' \
  datasets/scenarios/valley.ini > "$dir/changed-$draw.ini"
printf "\n[changes]\nseed = %d\nremove = 3\nadd = 3\nradius = 0.75\nmin_distance = 4\nmax_distance = 25\n" "$draw" \
  >> "$dir/changed-$draw.ini"
build/apps/swslam-sim -q --scenario "$dir/changed-$draw.ini" --output "$dir/data-$draw" > /dev/null
