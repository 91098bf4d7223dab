#!/usr/bin/env bash
# How runs start: each corrected CARMEN log cut into short windows (LEN scans, one starting at
# every STEP-th scan), each window run on its own, laser only, deterministic, with
# config/default.ini, and scored by its ATE against the log's reference poses. A run that
# starts while moving has no motion to predict from and a map of one scan; a wrong decision
# in its first scans (a turn in a symmetric room, a slide along a corridor) leaves the whole
# window off. Per log it prints the windows run, the median, 90th percentile and largest ATE,
# how many end over 0.3 m, and the worst windows (doc/tracking.md, "How runs start"). Then,
# per window, the scans' own optimum near the reference (swslam-eval laser-optimum): its
# median distance from the reference and how many windows have it over 0.3 m. Where the
# optimum stays near the reference and the run does not, the run's error is its own
# decisions', not a disagreement between the scans and the reference.
# Usage: scripts/bench-starts.sh [CARMEN_DIR]   (default ../shared/datasets; needs a build:
#        scripts/build.sh). Environment: LEN (60 scans), STEP (10 scans), WORST (3 windows).
set -euo pipefail
cd "$(dirname "$0")/.."
carmen_dir=${1:-../shared/datasets}
len=${LEN:-60} step=${STEP:-10} worst=${WORST:-3}
for v in "$len" "$step" "$worst"; do
  [[ $v =~ ^[0-9]+$ && $v -gt 0 ]] || { echo "bench-starts: LEN, STEP and WORST must be positive integers" >&2; exit 2; }
done
bin=build/apps
[[ -x $bin/swslam && -x $bin/swslam-carmen2rawlog ]] || { echo "bench-starts: build first (scripts/build.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

shopt -s nullglob
logs=("$carmen_dir"/*-corrected.log.gz)
((${#logs[@]})) || { echo "bench-starts: no *-corrected.log.gz in $carmen_dir" >&2; exit 1; }
echo "# windows of $len scans, one starting at every ${step}th scan; ATE in m against the reference"
echo "| log | windows | median | 90 % | largest | over 0.3 m | worst windows (first scan: ATE) | the scans' optimum: median, over 0.3 m |"
echo "|---|---|---|---|---|---|---|---|"
for log in "${logs[@]}"; do
  name=$(basename "$log" -corrected.log.gz)
  zcat -f "$log" | awk '$1 == "FLASER"' > "$work/flaser"
  scans=$(wc -l < "$work/flaser")
  : > "$work/ates"
  for ((from = 0; from + len <= scans; from += step)); do
    awk -v from="$from" -v len="$len" 'NR > from && NR <= from + len' "$work/flaser" > "$work/window.log"
    "$bin/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps -i "$work/window.log" \
      -o "$work/window.rawlog" --ground-truth "$work/window.tum" > /dev/null 2>&1
    rm -rf "$work/out"
    if ! "$bin/swslam" -c config/default.ini -i "$work/window.log" -g "$work/window.tum" -o "$work/out" -d -q \
         --no-odometry --no-render > /dev/null 2>&1; then
      echo "bench-starts: swslam failed on $name from scan $from" >&2
      exit 1
    fi
    ate=$(grep -F '| ATE (rmse)' "$work/out/summary.md" | awk -F'|' '{gsub(/[ m]/, "", $3); print $3}')
    optimum=nan
    if "$bin/swslam-eval" laser-optimum "$work/window.tum" "$work/window.rawlog" -c config/default.ini \
         -o "$work/optimum.tum" > /dev/null 2>&1; then
      optimum=$("$bin/swslam-eval" ate "$work/optimum.tum" "$work/window.tum" 2> /dev/null |
        awk -F= '$1 == "ate_rmse" { print $2 }')
    fi
    echo "$from $ate ${optimum:-nan}" >> "$work/ates"
  done
  sort -k2,2g "$work/ates" | awk -v name="$name" -v worst="$worst" '
    { from[NR] = $1; ate[NR] = $2; if ($2 > 0.3) over++ }
    $3 != "nan" { opt[++n_opt] = $3; if ($3 > 0.3) opt_over++ }
    END {
      if (NR == 0) { printf "| %s | 0 (shorter than a window) | | | | | | |\n", name; exit }
      optimum = "none computed"
      if (n_opt > 0) {
        for (i = 2; i <= n_opt; i++) for (k = i; k > 1 && opt[k] < opt[k - 1]; k--) { t = opt[k]; opt[k] = opt[k - 1]; opt[k - 1] = t }
        mo = (n_opt % 2) ? opt[(n_opt + 1) / 2] : (opt[n_opt / 2] + opt[n_opt / 2 + 1]) / 2
        optimum = sprintf("%.4f, %d of %d", mo, opt_over + 0, n_opt)
      }
      m = (NR % 2) ? ate[(NR + 1) / 2] : (ate[NR / 2] + ate[NR / 2 + 1]) / 2
      p = ate[int(0.9 * (NR - 1)) + 1]  # nearest rank below
      list = ""
      for (k = NR; k > NR - worst && k >= 1; k--) list = list sprintf("%s%s: %.4f", (list == "" ? "" : ", "), from[k], ate[k])
      printf "| %s | %d | %.4f | %.4f | %.4f | %d | %s | %s |\n", name, NR, m, p, ate[NR], over + 0, list, optimum
    }'
done
