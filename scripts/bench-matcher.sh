#!/usr/bin/env bash
# The figures of doc/plicp.md: swslam-bench-matcher on the bundled lake-short dataset
# (1081 rays over 270 deg) and on every corrected CARMEN log found in ../shared/datasets
# (or the folder given), converted laser-only with their reference poses, each with the rows
# of --floor (plicp-floor, search-floor: doc/plicp.md); then a summary table
# per log and initial guess (share of pairs under 5 cm, RMSE, median time of plicp,
# plicp+search and CICP classic).
# The corrected logs' reference poses carry errors of a few cm of their own. So each CARMEN
# log is scored a second time against the scans' own optimum near the reference
# (swslam-eval laser-optimum, doc/evaluation.md), with a second table. Before it, per log, the
# share of the optimum's consecutive motions within 5 cm of the reference's: no matcher
# whose result the scans support does much better than that against the reference.
# Under each table, per log: the pairs plicp+search puts 5 cm or more off from identity, and how
# many of them the pair's own scans support the reference in (swslam-bench-matcher --misses):
# the best share any choice made from the pair alone could reach.
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
run() {  # rows-file name rawlog gt: the rows, also kept for the summary
  echo "# $2" | tee -a "$work/$1"
  "${pin[@]}" "$bin/swslam-bench-matcher" --input "$3" --ground-truth "$4" --config config/default.ini --floor \
    --misses | tee -a "$work/$1"
}
: > "$work/rows"
: > "$work/rows-optimum"
: > "$work/agreement"
run rows lake-short datasets/lake-short/lake-short.rawlog datasets/lake-short/lake-short.gt.tum
shopt -s nullglob
for log in "$carmen_dir"/*-corrected.log.gz; do
  name=$(basename "$log" -corrected.log.gz)
  "$bin/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps -i "$log" \
    -o "$work/$name.rawlog" --ground-truth "$work/$name.tum" > /dev/null
  run rows "$name" "$work/$name.rawlog" "$work/$name.tum"
  if ! "$bin/swslam-eval" laser-optimum "$work/$name.tum" "$work/$name.rawlog" -c config/default.ini \
       -o "$work/$name.optimum.tum" > "$work/optimum.log" 2>&1; then
    echo "# $name: no optimum of its scans (swslam-eval laser-optimum failed; not scored against it):"
    sed 's/^/#   /' "$work/optimum.log"
    continue
  fi
  echo "# $name scored against the scans' own optimum near the reference"
  run rows-optimum "$name" "$work/$name.rawlog" "$work/$name.optimum.tum"
  # The optimum's consecutive motions against the reference's: the share within 5 cm
  # (swslam-eval's RPE, the translation error of the relative motion the matcher rows measure).
  "$bin/swslam-eval" ate "$work/$name.optimum.tum" "$work/$name.tum" |
    awk -F= -v name="$name" '$1 == "rpe_pairs" { n = $2 } $1 == "rpe_trans_within_5cm" { share = $2 }
      END { printf "%s %.1f %d\n", name, 100 * share, n }' >> "$work/agreement"
done

# Summary per log and initial guess: share of pairs under 5 cm, translation RMSE, median time.
summary() {
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
    }' "$1"
}
# The misses of plicp+search from identity, and how many of them the pair's own scans support
# (swslam-bench-matcher --misses): the best share under 5 cm any choice made from a pair alone
# could reach.
misses() {
  awk '
    /^# / && NF == 2 { log_name = $2; next }
    /^misses / {
      for (k = 2; k <= NF; k++) { split($k, kv, "="); f[kv[1]] = kv[2] }
      printf "- %s: %d misses of %d pairs, %d of them supported by the pair: at most %.1f %% under 5 cm\n",
        log_name, f["misses"], f["pairs"], f["supported"], 100 * f["best_frac_under_5cm"]
    }' "$1"
}
echo
echo "## Against the reference poses"
summary "$work/rows"
echo
echo "plicp+search from identity, its misses (5 cm or more) and those the pair's own scans support:"
misses "$work/rows"
if [[ -s $work/agreement ]]; then
  echo
  echo "## Against the scans' own optimum near the reference (swslam-eval laser-optimum)"
  echo "The optimum's consecutive motions within 5 cm of the reference's:"
  awk '{ printf "- %s: %.1f %% of %d\n", $1, $2, $3 }' "$work/agreement"
  echo
  summary "$work/rows-optimum"
  echo
  echo "plicp+search from identity, its misses (5 cm or more) and those the pair's own scans support:"
  misses "$work/rows-optimum"
fi
