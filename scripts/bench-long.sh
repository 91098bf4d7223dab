#!/usr/bin/env bash
# Issue 42's long-mission figures, deterministic, one core, config/default.ini:
#  1. the valley path driven LAPS times (default 10: about 5 km, 131,480 scans; the same
#     waypoints repeated, as bench-valley.sh section 8 does for 4): peak RSS, ATE, nodes and
#     edges, the memory and graph at the end of each lap, each lap's slowest tracked scan and
#     slowest full optimization, and the end of the run; out/bench-long/long.png plots memory
#     (RSS sampled every 0.5 s) and graph size against distance, the first lap (new shore)
#     apart from the revisits (scripts/plot-long.py; needs python3-matplotlib);
#  2. the valley cut at its middle, the first half saved as a session (--save-session) and the
#     second resumed from it twice (--resume): the ATE of the nodes and of the two halves'
#     trajectories against the uninterrupted run's, and whether the two resumes are the same
#     byte for byte (cutting needs rawlog-edit, from mrpt-apps);
#  3. what changed: the valley saved as a session, then driven again with other sensor noise
#     and three rocks taken away and three put (swslam-sim [changes], three draws), resumed:
#     each change found or missed, and the false changes (scripts/score-changes.py).
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

echo "== 1. the valley path driven $laps times"
read -r peak_kb wall < "$out/time"
field() { grep -F "| $1" "$out/run/summary.md" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }
echo "valley path x $laps: $(field 'Scans processed'); $(field 'Travelling distance'); wall $wall s ($(field 'Sensor time'))"
echo "peak RSS $((peak_kb / 1024)) MB; ATE $(field 'ATE (rmse)'); nodes $(field 'Number of graph nodes'), keyframes merged into them $(field 'Keyframes merged' || true); constraints (loops) $(field 'Number of graph constraints')"
/usr/bin/python3 scripts/plot-long.py "$out/run/stats.csv" "$out/data/valley-laps.gt.tum" "$out/rss.txt" "$laps" "$out/long.png"
rm -rf "$out/data"

echo "== 2. the valley cut at its middle, saved as a session and resumed"
if ! command -v rawlog-edit > /dev/null; then
  echo "skipped: needs rawlog-edit (apt-get install mrpt-apps)"
  exit 0
fi
[[ -f datasets/valley/valley.rawlog ]] || bash scripts/gen-datasets.sh valley > /dev/null
s=$out/session
mkdir -p "$s"
entries=$(rawlog-edit --info -i datasets/valley/valley.rawlog 2>/dev/null | awk -F: '/Overall number of objects/ { print $2 + 0 }')
half=$(( ${entries:-26296} / 2 ))
rawlog-edit --cut --to-index $((half - 1)) -i datasets/valley/valley.rawlog -o "$s/first.rawlog" -w > /dev/null 2>&1
rawlog-edit --cut --from-index "$half" -i datasets/valley/valley.rawlog -o "$s/second.rawlog" -w > /dev/null 2>&1
run() { taskset -c 0 "$bin/swslam" -d -q --no-render "$@" > /dev/null 2>> "$s/runs.log"; }
run -c config/default.ini -i datasets/valley/valley.rawlog -o "$s/whole" --save-session "$s/valley"
run -c config/default.ini -i "$s/first.rawlog" -o "$s/first" --save-session "$s/saved"
run -i "$s/second.rawlog" -o "$s/resumed-1" --resume "$s/saved"
run -i "$s/second.rawlog" -o "$s/resumed-2" --resume "$s/saved"
ate() { "$bin/swslam-eval" ate "$1" datasets/valley/valley.gt.tum | awk -F= '/^ate_rmse/ { printf "%.4f m", $2 }'; }
cat "$s/first/trajectory.tum" "$s/resumed-1/trajectory.tum" > "$s/halves.tum"
nodes() { grep -vc "^#" "$1"; }
echo "nodes: session $(nodes "$s/saved/keyframes.tum"), after the resume $(nodes "$s/resumed-1/keyframes.tum"), uninterrupted $(nodes "$s/whole/keyframes.tum")"
echo "ATE of the nodes: resumed $(ate "$s/resumed-1/keyframes.tum"), uninterrupted $(ate "$s/whole/keyframes.tum")"
echo "ATE of every scan: the two halves $(ate "$s/halves.tum"), uninterrupted $(ate "$s/whole/trajectory.tum")"
same=yes
for f in trajectory.tum keyframes.tum graph.graph map.gridmap.gz; do cmp -s "$s/resumed-1/$f" "$s/resumed-2/$f" || same="no ($f differs)"; done
echo "two resumes byte for byte the same: $same"
rm -f "$s"/*.rawlog

echo "== 3. what changed: the valley again with three rocks taken away and three put, resumed from section 2's session"
for draw in 1 2 3; do
  bash scripts/changed-valley.sh "$draw" "$s"
  run -i "$s/data-$draw/changed-$draw.rawlog" -o "$s/changed-$draw" --resume "$s/valley"
  echo "draw $draw:"
  /usr/bin/python3 scripts/score-changes.py datasets/valley/valley.gt.tum "$s/data-$draw/changed-$draw.changes.csv" \
    "$s/changed-$draw/changes.md"
  rm -rf "$s/data-$draw"
done
