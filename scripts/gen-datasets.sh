#!/usr/bin/env bash
# Builds swslam-sim and generates the simulated datasets of datasets/scenarios/ into
# datasets/NAME/ (rawlog, ground truth in TUM and MRPT text, world picture), printing
# each run's figures (scans/s, valid rays, file sizes).
# Usage: scripts/gen-datasets.sh [NAME...]     (default: every scenario)
set -euo pipefail
cd "$(dirname "$0")/.."

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build --target swslam-sim -j "$(nproc)" > /dev/null

names=("$@")
if ((${#names[@]} == 0)); then
  for f in datasets/scenarios/*.ini; do names+=("$(basename "$f" .ini)"); done
fi
for name in "${names[@]}"; do
  build/apps/swslam-sim --scenario "datasets/scenarios/$name.ini" --output "datasets/$name"
done
