#pragma once
// Ceres (sparse normal Cholesky) on a pose graph, for swslam-bench-graph only: Ceres is no
// dependency of the library.

#include <swslam/bench/graph_solvers.h>

/** Optimizes a copy of `graph` with Ceres `repeats` times (the same residual as ours). */
swslam::bench::SolverRun runCeres(const swslam::graph::PoseGraph& graph, int repeats);
