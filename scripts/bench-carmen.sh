#!/usr/bin/env bash
# The corrected CARMEN logs, laser only, with config/default.ini (no per-dataset tuning): each
# log's ATE against its reference poses, graph size, and the scans tracked by fallback, the
# ambiguous ones and those of them the prediction decided along a direction (doc/tracking.md).
# Needs a built tree (scripts/build.sh).
# Then the same logs played backwards in time (each log's FLASER lines in reverse order, their
# timestamps mirrored): the same scans, met in another order, so tracking takes other decisions;
# a check that the first table is not one lucky sequence of them. Last, each log started a
# quarter, half and three quarters of the way through (the scans before dropped): how a run
# starts while moving, without a motion to predict from.
# Per run also what the scans allow (swslam-eval laser-optimum, doc/evaluation.md): `support`,
# their own optimum started at the reference, its distance from it; `target`, the larger of
# 0.3 m and support + 0.2 m, and whether the ATE meets it; `own-basin`, their optimum started
# at the run's result, its distance from the run / its ATE against the reference (a run far off
# whose own result the scans hold as well sits in a basin they do not contradict).
# Usage: scripts/bench-carmen.sh [CARMEN_DIR] [OUT_DIR]   (defaults ../shared/datasets,
# out/bench-carmen); swslam's outputs go to OUT_DIR/<log>/, OUT_DIR/<log>-reversed/ and
# OUT_DIR/<log>-from-<scan>/. SWSLAM_BUILD=DIR runs another build's programs, with the
# config/default.ini of that build's source tree (scripts/compare-builds.sh does).
set -euo pipefail
cd "$(dirname "$0")/.."
carmen_dir=${1:-../shared/datasets}
out=${2:-out/bench-carmen}
build=${SWSLAM_BUILD:-build}
bin=$build/apps
cfg=$(sed -n 's/^swslam_SOURCE_DIR:STATIC=//p' "$build/CMakeCache.txt")/config/default.ini
mkdir -p "$out"
field() { grep -F "| $1" "$2" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }
# One log: convert (laser only, for the reference poses), run, print its row.
run() {  # name carmen-log
  local name=$1 log=$2
  rm -rf "${out:?}/$name"  # no stale results
  "$bin/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps -i "$log" -o "$out/$name.rawlog" \
    --ground-truth "$out/$name.gt.tum" > /dev/null 2>&1
  "$bin/swslam" -c $cfg -i "$log" -g "$out/$name.gt.tum" -o "$out/$name" -d -q --no-odometry \
    --no-render > /dev/null 2>&1 || true
  local s=$out/$name/summary.md
  if [[ ! -f $s ]]; then echo "$name: swslam failed (see: $bin/swslam -c $cfg -i $log -o $out/$name -d --no-odometry)"; return; fi
  local ate support own own_ate target ok
  ate=$(field 'ATE (rmse)' "$s" | awk '{print $1}')
  support=$(optimum "$out/$name.gt.tum" "$out/$name.rawlog")
  own=$(optimum "$out/$name/trajectory.tum" "$out/$name.rawlog" "$out/$name/own-optimum.tum")
  own_ate=$("$bin/swslam-eval" ate "$out/$name/own-optimum.tum" "$out/$name.gt.tum" 2> /dev/null | value ate_rmse)
  read -r target ok < <(awk -v a="$ate" -v s="$support" \
    'BEGIN { if (s == "") { print "? ?"; exit }  # no optimum: no target
            t = s + 0.2; if (t < 0.3) t = 0.3; printf "%.3f %s\n", t, (a + 0 <= t ? "yes" : "no") }')
  printf "%-28s %-8s %-7s %-24s %-9s %-9s %-9s %-8s %-7s %-3s %s\n" "$name" "$ate" \
    "$(field 'Number of graph nodes' "$s")" "$(field 'Number of graph constraints' "$s")" \
    "$(field 'Scans tracked by fallback' "$s")" "$(field 'Ambiguous scans' "$s")" \
    "$(field 'of them decided by the prediction' "$s")" "$(metres "$support")" "$target" "$ok" \
    "$(metres "$own") / $(metres "$own_ate")"
}
# The scans' own optimum started at a trajectory: its distance from it (m); written to OUT.tum
# when given.
optimum() {  # trajectory.tum log.rawlog [OUT.tum]
  local args=(laser-optimum "$1" "$2" -c "$cfg")
  [[ $# -lt 3 ]] || args+=(-o "$3")
  "$bin/swslam-eval" "${args[@]}" 2> /dev/null | value moved_rmse_m
}
# The value of swslam-eval's `KEY=value` line.
value() { sed -n "s/^$1=//p"; }
# A distance to four decimals, `?` when there is none.
metres() { if [[ -n $1 ]]; then printf '%.4f' "$1"; else printf '?'; fi; }
# A log played backwards: its FLASER lines in reverse order, each timestamp t mirrored to
# first + last - t (so they increase again).
reversed() {  # carmen-log out.log
  zcat -f "$1" | awk '
    $1 == "FLASER" { line[++n] = $0; t = $(NF - 2) + 0; if (n == 1 || t < lo) lo = t; if (n == 1 || t > hi) hi = t }
    END {
      for (k = n; k >= 1; k--) {
        $0 = line[k]; t = sprintf("%.6f", lo + hi - $(NF - 2)); $(NF - 2) = t; $NF = t; print
      }
    }' > "$2"
}
# A log started at its FLASER line `from` (0-based): the lines before dropped.
started() {  # carmen-log from out.log
  zcat -f "$1" | awk -v from="$2" '$1 == "FLASER" && n++ >= from' > "$3"
}
printf "%-28s %-8s %-7s %-24s %-9s %-9s %-9s %-8s %-7s %-3s %s\n" log "ATE (m)" nodes "constraints (loops)" fallback \
  ambiguous decided support target ok "own-basin (m)"
logs=("$carmen_dir"/*-corrected.log.gz)
for log in "${logs[@]}"; do
  [[ -f $log ]] || continue
  run "$(basename "$log" -corrected.log.gz)" "$log"
done
echo "# played backwards"
for log in "${logs[@]}"; do
  [[ -f $log ]] || continue
  name=$(basename "$log" -corrected.log.gz)-reversed
  reversed "$log" "$out/$name.log"
  run "$name" "$out/$name.log"
done
echo "# started part-way"
for log in "${logs[@]}"; do
  [[ -f $log ]] || continue
  scans=$(zcat -f "$log" | awk '$1 == "FLASER"' | wc -l)
  for quarter in 1 2 3; do
    from=$((scans * quarter / 4))
    name=$(basename "$log" -corrected.log.gz)-from-$from
    started "$log" "$from" "$out/$name.log"
    run "$name" "$out/$name.log"
  done
done
