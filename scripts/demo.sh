#!/usr/bin/env bash
# README command 1: install dependencies, build, and run swslam on the bundled
# natural-environment dataset (datasets/lake-short: a simulated cluttered lake bank, 2461 scans
# of 1081 rays over 270 deg at 40 Hz, with ground truth). Writes the map picture, the
# trajectory, the graph, stats.csv and the Table I summary into out/lake-short/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh > build.log 2>&1 || { tail -50 build.log; exit 1; }
log=datasets/lake-short/lake-short
out=out/lake-short
build/apps/swslam --config config/default.ini --input "$log.rawlog" --output "$out" \
  --ground-truth "$log.gt.tum"
# Debian's python3 (with python3-matplotlib) draws the paper's Fig. 6 and Fig. 7.
if /usr/bin/python3 -c 'import matplotlib' 2> /dev/null; then
  /usr/bin/python3 scripts/plot-stats.py "$out/stats.csv" "$out"
fi
echo "Map pictures: $out/map.png (map, trajectory, start and end) and $out/render.png (the same with the pose graph)"
echo "Table I summary: $out/summary.md; per-scan figures: $out/stats.csv (plots: $out/fig6.png, $out/fig7.png)"
