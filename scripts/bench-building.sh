#!/usr/bin/env bash
# The simulated symmetric building (datasets/scenarios/building.ini: a ring corridor and a cross
# of corridors between four equal blocks, the same under a quarter turn; 181 rays, 30 m, scans
# 1.3 m apart, turns of up to 70 deg between two scans), laser only: whether a turn taken the
# wrong way at a junction, or a start section slid along a corridor, is undone by the
# revisits. Prints what scripts/bench-sim-laser.sh prints.
# Usage: scripts/bench-building.sh [OUT_DIR]   (default out/bench-building; generates
#        datasets/building/ if missing; needs a build: scripts/build.sh)
exec "$(dirname "$0")/bench-sim-laser.sh" building "$@"
