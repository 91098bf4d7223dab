#!/usr/bin/env bash
# The simulated campus (datasets/scenarios/campus.ini: 1.95 km among sparse trees, a figure
# eight whose crossing comes back after some 800 m, then its first 300 m driven again; 180
# rays, 80 m, scans 1 m apart), laser only: how far tracking drifts where no loop is near, and
# whether the revisits are found. Prints what scripts/bench-sim-laser.sh prints.
# Usage: scripts/bench-campus.sh [OUT_DIR]   (default out/bench-campus; generates
#        datasets/campus/ if missing; needs a build: scripts/build.sh)
exec "$(dirname "$0")/bench-sim-laser.sh" campus "$@"
