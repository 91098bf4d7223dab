#!/usr/bin/env bash
# Issue 42's long-mission figures: the valley path driven LAPS times (default 10: about 5 km,
# 131,480 scans; the same waypoints repeated, as bench-valley.sh section 8 does for 4),
# deterministic, one core, config/default.ini. Prints peak RSS, ATE, nodes and edges, the
# memory and graph at the end of each lap, each lap's slowest tracked scan and slowest full
# optimization, and the end of the run; writes out/bench-long/long.png, memory (RSS sampled
# every 0.5 s) and graph size against distance, the first lap (new shore) apart from the
# revisits (scripts/plot-long.py; needs python3-matplotlib).
# Usage: scripts/bench-long.sh [LAPS]   (expects build/ from scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
laps=${1:-10}
[[ $laps =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [LAPS]  (a positive whole number)" >&2; exit 2; }
bin=build/apps
[[ -x $bin/swslam && -x $bin/swslam-sim ]] || { echo "bench-long: no $bin/swslam; run scripts/build.sh first" >&2; exit 2; }
out=out/bench-long
rm -rf "$out" && mkdir -p "$out"

awk -v n="$laps" '/^waypoints *=/ { w = $0; sub(/^waypoints *= */, "", w); s = w; for (i = 1; i < n; i++) s = s ", " w;
  print "waypoints = " s; next } { print }' datasets/scenarios/valley.ini > "$out/valley-laps.ini"
"$bin/swslam-sim" -q --scenario "$out/valley-laps.ini" --output "$out/data" > /dev/null

/usr/bin/time -f "%M %e" -o "$out/time" taskset -c 0 "$bin/swslam" -c config/default.ini \
  -i "$out/data/valley-laps.rawlog" -g "$out/data/valley-laps.gt.tum" -o "$out/run" -d -q --no-render \
  > "$out/run.log" 2>&1 &
pid=$!
# The run's resident memory, sampled by the wall clock (time since the start, kB).
start=$(date +%s.%N)
while kill -0 "$pid" 2> /dev/null; do
  child=$(pgrep -P "$pid" swslam || true)
  [[ -n $child ]] && awk -v t="$(date +%s.%N)" -v s="$start" '/^VmRSS:/ { printf "%.2f %d\n", t - s, $2 }' \
    "/proc/$child/status" 2> /dev/null >> "$out/rss.txt" || true
  sleep 0.5
done
wait "$pid" || { echo "bench-long: swslam failed"; tail -20 "$out/run.log"; exit 1; }

read -r peak_kb wall < "$out/time"
field() { grep -F "| $1" "$out/run/summary.md" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }
echo "valley path x $laps: $(field 'Scans processed'); $(field 'Travelling distance'); wall $wall s ($(field 'Sensor time'))"
echo "peak RSS $((peak_kb / 1024)) MB; ATE $(field 'ATE (rmse)'); nodes $(field 'Number of graph nodes'); constraints (loops) $(field 'Number of graph constraints')"
/usr/bin/python3 scripts/plot-long.py "$out/run/stats.csv" "$out/data/valley-laps.gt.tum" "$out/rss.txt" "$laps" "$out/long.png"
rm -rf "$out/data"
