#!/usr/bin/env bash
# Issue 42's localization figures, deterministic, one core, config/default.ini
# (doc/localization.md):
#  1. the valley mapped and saved as a session; a second valley run with other sensor noise
#     (swslam-sim, noise_seed 777) localized on it with no initial pose, scored against its
#     reference poses (swslam-bench-localize): the whole log from its first scan, 100 random
#     starts each given 2 s of log to relocalize in, and lake-short, another place, which must
#     stay lost; with the odometry and laser only;
#  2. what changed: the valley again with three rocks taken away and three put (swslam-sim
#     [changes], three draws, as bench-long.sh section 3), localized on the session: each
#     change found or missed, and the false changes (scripts/score-changes.py);
#  3. a real outdoor log: the UAL campus loop (SICK, 361 rays, 81 m; ../shared/datasets) mapped
#     with its odometry over its first two thirds and saved as a session, then the whole log
#     localized on it: the states of its scans (the last third leaves the map and comes back to
#     its start), against the session's own trajectory and against the whole log's run
#     (scripts/localization-errors.py);
#  4. side by side with MRPT's pf-localization on the same map and the first 30 s of the same
#     log: from no initial pose (50,000 particles over the map's free cells; three runs, its
#     particles drawn anew each run) and from a start known to +-0.5 m and +-10 deg (5,000
#     particles); scored by scripts/pf-errors.py (needs mrpt-apps and python3-numpy).
#     pf-localization takes some ten minutes.
# Usage: scripts/bench-localize.sh [UAL_RAWLOG]   (expects build/ from scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/apps
[[ -x $bin/swslam-bench-localize ]] || { echo "bench-localize: no $bin/swslam-bench-localize; run scripts/build.sh first" >&2; exit 2; }
[[ -f datasets/valley/valley.rawlog ]] || bash scripts/gen-datasets.sh valley
ual=${1:-../shared/datasets/ual-campus-2014-05-23.rawlog}
out=$PWD/out/bench-localize
rm -rf "$out" && mkdir -p "$out"

taskset -c 0 "$bin/swslam" -c config/default.ini -i datasets/valley/valley.rawlog -o "$out/map" -d -q --no-render \
  --save-session "$out/session" > "$out/map.log" 2>&1
awk '/^noise_seed/ { next } { print } /^seed *=/ { print "noise_seed = 777" }' datasets/scenarios/valley.ini \
  > "$out/valley2.ini"
"$bin/swslam-sim" -q --scenario "$out/valley2.ini" --output "$out/data" > /dev/null
log=$out/data/valley2.rawlog
truth=$out/data/valley2.gt.tum
common=(-m "$out/session" --map-truth datasets/valley/valley.gt.tum -i "$log" -t "$truth")

echo "== 1. localization on the valley's session, a second valley run (other sensor noise)"
echo "-- with its odometry"
taskset -c 0 "$bin/swslam-bench-localize" "${common[@]}" --elsewhere datasets/lake-short/lake-short.rawlog
echo
echo "-- laser only"
taskset -c 0 "$bin/swslam-bench-localize" "${common[@]}" --no-odometry

echo
echo "== 2. what changed: the valley with three rocks taken away and three put, localized on the session"
for draw in 1 2 3; do
  bash scripts/changed-valley.sh "$draw" "$out"
  taskset -c 0 "$bin/swslam-localize" -m "$out/session" -i "$out/data-$draw/changed-$draw.rawlog" \
    -o "$out/changed-$draw" > /dev/null
  echo "draw $draw:"
  /usr/bin/python3 scripts/score-changes.py datasets/valley/valley.gt.tum "$out/data-$draw/changed-$draw.changes.csv" \
    "$out/changed-$draw/changes.md"
  rm -rf "$out/data-$draw"
done

echo
echo "== 3. a real outdoor log: the UAL campus, its first two thirds mapped, the whole log localized"
if [[ ! -f $ual ]] || ! command -v rawlog-edit > /dev/null; then
  echo "skipped: needs $ual and rawlog-edit (apt-get install mrpt-apps)"
else
  entries=$(rawlog-edit --info -i "$ual" 2>/dev/null | awk -F: '/Overall number of objects/ { print $2 + 0 }')
  rawlog-edit --cut --to-index $((entries * 2 / 3)) -i "$ual" -o "$out/ual-first.rawlog" -w > /dev/null 2>&1
  taskset -c 0 "$bin/swslam" -c config/default.ini -i "$out/ual-first.rawlog" -o "$out/ual-first" -d -q --no-render \
    --save-session "$out/ual-session" > /dev/null 2>&1
  taskset -c 0 "$bin/swslam" -c config/default.ini -i "$ual" -o "$out/ual-whole" -d -q --no-render > /dev/null 2>&1
  taskset -c 0 "$bin/swslam-localize" -m "$out/ual-session" -i "$ual" -o "$out/ual-localized" | sed 's/^/   /'
  echo "-- against the session's own run (the first two thirds)"
  /usr/bin/python3 scripts/localization-errors.py "$out/ual-localized/localization.csv" "$out/ual-first/trajectory.tum"
  echo "-- against the whole log's run (its loop closed: the session's map differs from it by its drift)"
  /usr/bin/python3 scripts/localization-errors.py "$out/ual-localized/localization.csv" "$out/ual-whole/trajectory.tum"
  rm -f "$out/ual-first.rawlog"
fi

echo
echo "== 4. side by side with MRPT's pf-localization: the first 30 s of the same log, the same map"
if ! command -v pf-localization > /dev/null || ! command -v rawlog-edit > /dev/null; then
  echo "skipped: needs pf-localization and rawlog-edit (apt-get install mrpt-apps)"
  exit 0
fi
# 1200 scans, each after its odometry reading: pf-localization's step 2k+1 is scan k.
rawlog-edit --cut --to-index 2399 -i "$log" -o "$out/first30s.rawlog" -w > /dev/null 2>&1
"$bin/swslam-bench-localize" -m "$out/session" --map-truth datasets/valley/valley.gt.tum -i "$out/first30s.rawlog" \
  -t "$truth" --starts 0 | sed -n '/^1\./,$p'
pf_ini() {  # NAME PARTICLES MODE X0 X1 Y0 Y1 [YAW0 YAW1]
  sed -e "s|^map_file=.*|map_file=$out/session/map.gridmap.gz|" -e "s|^rawlog_file=.*|rawlog_file=$out/first30s.rawlog|" \
    -e "s|^logOutput_dir=.*|logOutput_dir=$out/pf-$1|" -e "s|^particles_count=.*|particles_count=$2|" \
    -e "s|^KLD_maxSampleSize=.*|KLD_maxSampleSize=$2|" -e "s|^init_PDF_mode=.*|init_PDF_mode=$3|" \
    -e "s|^init_PDF_min_x=.*|init_PDF_min_x=$4|" -e "s|^init_PDF_max_x=.*|init_PDF_max_x=$5|" \
    -e "s|^init_PDF_min_y=.*|init_PDF_min_y=$6|" -e "s|^init_PDF_max_y=.*|init_PDF_max_y=$7\ninit_PDF_min_yaw_deg=${8:--180}\ninit_PDF_max_yaw_deg=${9:-180}|" \
    -e "s|^SHOW_PROGRESS_3D_REAL_TIME *=.*|SHOW_PROGRESS_3D_REAL_TIME=false|" -e "s|^3DSceneFrequency=.*|3DSceneFrequency=100000|" \
    -e "s|^LF_maxRange=.*|LF_maxRange=60|" \
    /usr/share/mrpt/config_files/pf-localization/localization_demo_obsonly_rawlog.ini > "$out/pf-$1.ini"
}
# The map's frame is the first node's: the log starts at the origin, the map spans +-125 m.
pf_ini global 50000 0 -125 125 -125 125
pf_ini local 5000 1 -0.5 0.5 -0.5 0.5 -10 10
# pf-localization draws its particles from a seed of its own each run: the global start is run
# three times.
for run in global-1 global-2 global-3 local; do
  if [[ $run == local ]]; then
    echo "-- pf-localization, start known to +-0.5 m, +-10 deg (5,000 particles)"
  else
    cp "$out/pf-global.ini" "$out/pf-$run.ini"
    sed -i "s|^logOutput_dir=.*|logOutput_dir=$out/pf-$run|" "$out/pf-$run.ini"
    echo "-- pf-localization, no initial pose (50,000 particles over the free cells), run ${run#global-}"
  fi
  (cd "$out" && taskset -c 0 pf-localization "pf-$run.ini" < /dev/null > "pf-$run.log" 2>&1)
  /usr/bin/python3 scripts/pf-errors.py "$out/pf-$run.log" "$out/session/keyframes.tum" datasets/valley/valley.gt.tum \
    "$truth" "$(awk '!/^#/ { print $1; exit }' "$truth")" 40
done
