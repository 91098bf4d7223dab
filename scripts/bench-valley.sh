#!/usr/bin/env bash
# Issue 5's figures, all with config/default.ini (no per-dataset tuning):
#  1. valley (about 500 m, 40 Hz, 1081 rays) deterministic on one core: Table I, ATE, RPE,
#     throughput against real time, peak memory;
#  2. valley threaded: each module's max time, apart from full optimizations after loops;
#  3. valley over 10 noise seeds: ATE mean and std;
#  4. the corrected CARMEN logs laser-only (ATE; the ATE of a run given the reference motion as
#     odometry; how far the scans' own constraints pull the reference, swslam-eval
#     laser-optimum; and the scans' agreement at swslam's poses, at the reference poses and at
#     those two, swslam-eval consistency), and the open-water scenario;
#  5. MRPT's Telecom Faculty one-loop rawlog: the map before and after its loop closes;
#  6. MRPT's icp-slam on the valley rawlog: time and ATE;
#  7. MRPT's driving_in_office_obs.rawlog from CARMEN_DIR (no ground truth), laser only and
#     with odometry: each scan's motion against the log's odometry (scripts/odometry-steps.py;
#     needs rawlog-edit from mrpt-apps, and python3);
#  8. a long run, the valley path driven four times: throughput, graph module time, peak
#     memory and ATE, with the default rule for full optimizations and with the paper's.
# Usage: scripts/bench-valley.sh [CARMEN_DIR]   (default ../shared/datasets); writes out/bench-valley/
set -euo pipefail
cd "$(dirname "$0")/.."
carmen_dir=${1:-../shared/datasets}
bash scripts/install-deps.sh --with-tools > /dev/null ||
  echo "bench-valley: could not install mrpt-apps; sections 6 and 7 will say what they miss"
bash scripts/build.sh > build.log 2>&1 || { tail -50 build.log; exit 1; }
out=out/bench-valley
mkdir -p "$out"
bin=build/apps
cfg=config/default.ini
[[ -f datasets/valley/valley.rawlog ]] || bash scripts/gen-datasets.sh valley
[[ -f datasets/open-water/open-water.rawlog ]] || bash scripts/gen-datasets.sh open-water
field() { grep -F "| $1" "$2" | head -1 | awk -F'|' '{print $3}' | sed 's/^ *//; s/ *$//'; }

echo "== 1. valley, deterministic, one core"
/usr/bin/time -f "peak memory %M KiB, wall %e s" -o "$out/valley-det.time" \
  taskset -c 0 "$bin/swslam" -c $cfg -i datasets/valley/valley.rawlog -g datasets/valley/valley.gt.tum \
  -o "$out/valley-det" -d -q > /dev/null 2> "$out/valley-det.err"
cat "$out/valley-det/summary.md"
cat "$out/valley-det.time"

echo "== 2. valley, threaded (each module on its own thread)"
"$bin/swslam" -c $cfg -i datasets/valley/valley.rawlog -g datasets/valley/valley.gt.tum \
  -o "$out/valley-thr" -q > /dev/null 2> "$out/valley-thr.err"
grep -E "Sensor time|Execution time|ATE|RPE" "$out/valley-thr/summary.md"
awk -F, 'NR > 1 {
    if ($15 == 1) { if ($10 > fg) fg = $10; if ($11 > fm) fm = $11; nf++ }
    else { if ($10 > g) g = $10; if ($11 > m) m = $11 }
    if ($9 > t) t = $9
  }
  END { printf "max per scan [ms]: tracking %.2f, graph (window) %.2f, map %.2f; after the %d full optimizations: graph %.2f, map %.2f\n", t, g, m, nf, fg, fm }' \
  "$out/valley-thr/stats.csv"

echo "== 3. valley over 10 noise seeds (deterministic)"
seeds=$out/seeds
mkdir -p "$seeds"
for s in 1 2 3 4 5 6 7 8 9 10; do
  sed "s/^seed *= *\([0-9]*\)/seed = \1\nnoise_seed = $s/" datasets/scenarios/valley.ini > "$seeds/valley-$s.ini"
  "$bin/swslam-sim" -q --scenario "$seeds/valley-$s.ini" --output "$seeds/data-$s" > /dev/null
  "$bin/swslam" -c $cfg -i "$seeds/data-$s/valley-$s.rawlog" -g "$seeds/data-$s/valley-$s.gt.tum" \
    -o "$seeds/run-$s" -d -q --no-render > /dev/null 2>&1
  echo "seed $s: ATE $(field 'ATE (rmse)' "$seeds/run-$s/summary.md"), RPE 1 m $(field 'RPE, 1 m' "$seeds/run-$s/summary.md")"
  rm -rf "$seeds/data-$s"
done | tee "$out/seeds.txt"
awk '{ v = $4 + 0; s += v; q += v * v; n++ } END { m = s / n; printf "ATE over %d seeds: mean %.4f m, std %.4f m\n", n, m, sqrt((q - n * m * m) / (n - 1)) }' "$out/seeds.txt"

echo "== 4. corrected CARMEN logs (laser only) and open water"
# The laser-only runs and their ATE table (writes $out/<log>/, <log>.rawlog, <log>.gt.tum).
bash scripts/bench-carmen.sh "$carmen_dir" "$out"
for log in "$carmen_dir"/*-corrected.log.gz; do
  [[ -f $log ]] || continue
  name=$(basename "$log" -corrected.log.gz)
  echo "$name:"
  rm -rf "$out/$name-reference-odometry" "$out/$name-laser-optimum.tum"  # no stale results
  # The same run told the reference motion at every scan (odometry = the reference poses): how
  # far the laser alone takes it from the reference (doc/evaluation.md). Not a result to quote
  # as swslam's: it uses the reference.
  "$bin/swslam-carmen2rawlog" -q -w --laser-only --repair-timestamps --reference-odometry -i "$log" \
    -o "$out/$name-reference-odometry.rawlog" > /dev/null 2>&1
  "$bin/swslam" -c $cfg -i "$out/$name-reference-odometry.rawlog" -g "$out/$name.gt.tum" \
    -o "$out/$name-reference-odometry" -d -q --no-render > /dev/null 2>&1 || true
  echo "  with the reference motion as odometry: ATE $(field 'ATE (rmse)' "$out/$name-reference-odometry/summary.md")"
  # Where the scans' own constraints, matched from the reference, pull the reference (no
  # tracking decisions: doc/evaluation.md).
  "$bin/swslam-eval" laser-optimum "$out/$name.gt.tum" "$log" -c $cfg -o "$out/$name-laser-optimum.tum" \
    2> /dev/null | grep '^#' | sed 's|^# |  laser optimum from the reference: |' || true
  # How well the scans agree at the reference poses, at swslam's, and at the two experiments'
  # (doc/evaluation.md).
  # Only the trajectories this run wrote (a step that failed is left out, not replaced).
  compare=()
  for t in "$out/$name/trajectory.tum" "$out/$name-reference-odometry/trajectory.tum" "$out/$name-laser-optimum.tum"; do
    [[ -f $t ]] && compare+=(--compare "$t")
  done
  "$bin/swslam-eval" consistency "$out/$name.gt.tum" "$log" -c $cfg "${compare[@]}" \
    2> /dev/null | grep '^#' | sed "s|$out/||; s|^# |  consistency |" || true
done
"$bin/swslam" -c $cfg -i datasets/open-water/open-water.rawlog -g datasets/open-water/open-water.gt.tum \
  -o "$out/open-water" -d -q --no-render > /dev/null 2>&1
echo "open-water: ATE $(field 'ATE (rmse)' "$out/open-water/summary.md"), scans by fallback $(field 'Scans tracked by fallback' "$out/open-water/summary.md") of $(field 'Scans processed' "$out/open-water/summary.md"), ambiguous $(field 'Ambiguous scans' "$out/open-water/summary.md") (decided by the prediction $(field 'of them decided by the prediction' "$out/open-water/summary.md"))"

echo "== 5. MRPT Telecom Faculty one-loop rawlog"
telecom="/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
if [[ -f $telecom ]]; then
  "$bin/swslam" -c $cfg -i "$telecom" -o "$out/telecom-after" -d -q > /dev/null 2>&1
  first=$(awk -F, 'NR > 1 && $14 > 0 { print $1; exit }' "$out/telecom-after/stats.csv")
  if [[ -n $first ]]; then
    "$bin/swslam" -c $cfg -i "$telecom" -o "$out/telecom-before" -d -q --max-scans "$first" > /dev/null 2>&1
    echo "first loop at scan $first; constraints (loops) in the whole run: $(field 'Number of graph constraints' "$out/telecom-after/summary.md")"
    echo "map before: $out/telecom-before/render.png, after: $out/telecom-after/render.png"
  else
    echo "no loop closed"
  fi
fi

echo "== 6. MRPT icp-slam on the valley rawlog"
if command -v icp-slam > /dev/null; then
  work=$out/icp-slam
  mkdir -p "$work"
  sed -e 's|^SHOW_PROGRESS_3D_REAL_TIME=1|SHOW_PROGRESS_3D_REAL_TIME=0|' -e 's|^SAVE_3D_SCENE=1|SAVE_3D_SCENE=0|' \
      -e "s|^logOutput_dir=.*|logOutput_dir=$work/out|" \
      /usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini > "$work/icp.ini"
  start=$(date +%s.%N)
  icp-slam "$work/icp.ini" datasets/valley/valley.rawlog > "$work/log.txt" 2>&1
  end=$(date +%s.%N)
  # One logged pose per rawlog entry (odometry, scan): scan i is entry 2i+1; give it the
  # ground truth's timestamp, then score with swslam-eval.
  awk 'NR == FNR { if ($1 !~ /^#/) t[n++] = $1; next } ($1 + 1) % 2 == 0 { i = ($1 + 1) / 2 - 1; if (i < n) printf "%s %s %s 0 0 0 %.9f %.9f\n", t[i], $2, $3, sin($4 / 2), cos($4 / 2) }' \
    datasets/valley/valley.gt.tum "$work/out/log_estimated_path.txt" > "$work/icp-slam.tum"
  printf "icp-slam: %.1f s; " "$(echo "$end - $start" | bc)"
  "$bin/swslam-eval" ate "$work/icp-slam.tum" datasets/valley/valley.gt.tum | grep -E "^ate_rmse=" | head -1
  echo "swslam (deterministic, one core): $(field 'Sensor time' "$out/valley-det/summary.md"), ATE $(field 'ATE (rmse)' "$out/valley-det/summary.md")"
else
  echo "icp-slam not found (apt-get install mrpt-apps)"
fi

echo "== 7. MRPT office rawlog: per-scan motion against the log's odometry"
office=$carmen_dir/driving_in_office_obs.rawlog
if [[ -f $office ]] && command -v rawlog-edit > /dev/null && command -v python3 > /dev/null; then
  work=$out/office
  mkdir -p "$work"
  # rawlog-edit 2.5 writes its export beside its input, dropping the directory's last slash:
  # run it on a copy in the folder itself.
  cp "$office" "$work/office.rawlog"
  (cd "$work" && rawlog-edit -q -i office.rawlog --export-odometry-txt > /dev/null 2>&1)
  for mode in laser-only odometry; do
    flag=(); [[ $mode == laser-only ]] && flag=(--no-odometry)
    if ! "$bin/swslam" -c "$cfg" -i "$office" -o "$work/$mode" -d -q --no-render "${flag[@]}" > /dev/null 2>&1; then
      echo "$mode: swslam failed (see: $bin/swslam -c $cfg -i $office -o $work/$mode -d ${flag[*]})"
      continue
    fi
    echo "$mode: $(python3 scripts/odometry-steps.py "$work/$mode/trajectory.tum" "$work/office_odometry.txt" 2>&1), travelled $(field 'Travelling distance' "$work/$mode/summary.md")"
  done
else
  echo "skipped: needs $office, rawlog-edit (apt-get install mrpt-apps) and python3"
fi

echo "== 8. a long run: the valley path driven four times (about 2 km, 52,600 scans), deterministic, one core"
# Repeated laps close a loop at almost every node. With the default config only loops that
# disagree with the graph trigger a full optimization; the paper's rule (every loop) for
# comparison: [graph_optimizer] full_optimization_loop_xy = full_optimization_loop_theta_DEG = 0.
laps=$out/laps
mkdir -p "$laps"
awk '/^waypoints *=/ { w = $0; sub(/^waypoints *= */, "", w); print "waypoints = " w ", " w ", " w ", " w; next } { print }' \
  datasets/scenarios/valley.ini > "$laps/valley-laps.ini"
awk '{print} /^\[graph_optimizer\]/{print "full_optimization_loop_xy = 0"; print "full_optimization_loop_theta_DEG = 0"}' \
  "$cfg" > "$laps/every-loop.ini"
"$bin/swslam-sim" -q --scenario "$laps/valley-laps.ini" --output "$laps/data" > /dev/null
for run in default every-loop; do
  c=$cfg; [[ $run == every-loop ]] && c=$laps/every-loop.ini
  /usr/bin/time -f "peak memory %M KiB" -o "$laps/$run.time" taskset -c 0 "$bin/swslam" -c "$c" \
    -i "$laps/data/valley-laps.rawlog" -g "$laps/data/valley-laps.gt.tum" -o "$laps/$run" -d -q --no-render > /dev/null 2>&1
  s=$laps/$run/summary.md
  echo "$run: $(field 'Sensor time' "$s"); ATE $(field 'ATE (rmse)' "$s"); constraints (loops) $(field 'Number of graph constraints' "$s"); $(cat "$laps/$run.time")"
  # The last row holds the end of the run (final full optimization and refinement).
  awk -F, 'NR > 1 { if (prev != "") { split(prev, p, ","); g += p[10]; if (p[15] == 1) { nf++; fg += p[10]; if (p[10] > mf) mf = p[10] } } prev = $0 }
    END { split(prev, p, ","); printf "  graph module during the run %.1f s, %d full optimizations (max %.0f ms, %.1f s in all); end of run %.0f ms\n", g / 1000, nf, mf, fg / 1000, p[10] }' \
    "$laps/$run/stats.csv"
done
rm -rf "$laps/data"
