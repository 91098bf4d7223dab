#!/usr/bin/env bash
# The figures of doc/plicp.md: swslam-bench-matcher on the bundled lake-short dataset
# (1081 rays over 270 deg) and on every corrected CARMEN log found in ../shared/datasets
# (or the folder given), converted laser-only with their reference poses, each with the rows
# of --floor (plicp-floor, search-floor: doc/plicp.md); then a summary table
# per log and initial guess (share of pairs under 5 cm, RMSE, median time of plicp,
# plicp+search and CICP classic).
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
run() {  # name rawlog gt: the rows, also kept for the summary
  echo "# $1" | tee -a "$work/rows"
  "${pin[@]}" "$bin/swslam-bench-matcher" --input "$2" --ground-truth "$3" --config config/default.ini --floor |
    tee -a "$work/rows"
}
run lake-short datasets/lake-short/lake-short.rawlog datasets/lake-short/lake-short.gt.tum
shopt -s nullglob
for log in "$carmen_dir"/*-corrected.log.gz; do
  name=$(basename "$log" -corrected.log.gz)
  "$bin/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps -i "$log" \
    -o "$work/$name.rawlog" --ground-truth "$work/$name.tum" > /dev/null
  run "$name" "$work/$name.rawlog" "$work/$name.tum"
done

# Summary per log and initial guess: share of pairs under 5 cm, translation RMSE, median time.
echo
echo "| log | init | plicp: <5 cm, RMSE, median | plicp+search | cicp-classic |"
echo "|---|---|---|---|---|"
awk '
  /^# / && NF == 2 { log_name = $2; next }
  /^(plicp|plicp\+search|cicp-classic) / {
    for (k = 2; k <= NF; k++) { split($k, kv, "="); f[kv[1]] = kv[2] }
    cell[log_name, f["init"], $1] = sprintf("%.1f %%, %.3f m, %.0f us", 100 * f["frac_under_5cm"], f["trans_rmse_m"], f["median_us"])
    if (!((log_name, f["init"]) in seen)) { seen[log_name, f["init"]] = 1; order[++n] = log_name SUBSEP f["init"] }
  }
  END {
    for (k = 1; k <= n; k++) {
      split(order[k], key, SUBSEP)
      printf "| %s | %s | %s | %s | %s |\n", key[1], key[2], cell[key[1], key[2], "plicp"],
        cell[key[1], key[2], "plicp+search"], cell[key[1], key[2], "cicp-classic"]
    }
  }' "$work/rows"
