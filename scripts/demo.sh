#!/usr/bin/env bash
# README command 1: install dependencies, build, and run the main job on the bundled
# natural-environment dataset (datasets/lake-short: a simulated cluttered lake bank, 2461 scans
# of 1081 rays over 270 deg, with ground truth). For now the main job is the scan-matcher
# benchmark: swslam's PLICP against MRPT's ICP on every consecutive scan pair.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh > build.log 2>&1 || { tail -50 build.log; exit 1; }
log=datasets/lake-short/lake-short
mkdir -p out
build/apps/swslam-bench-matcher --input "$log.rawlog" --ground-truth "$log.gt.tum" \
  --config config/default.ini | tee out/bench-matcher-lake-short.txt
echo "Written: out/bench-matcher-lake-short.txt (one row per matcher and initial guess)"
