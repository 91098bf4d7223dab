#pragma once
// Ceres (sparse normal Cholesky) on a pose graph, for swslam-bench-graph only: Ceres is no
// dependency of the library.

#include <swslam/bench/graph_solvers.h>

#include <optional>

/** Which edges get Ceres' Cauchy loss, and its scale (GraphOptimizerParams::kernel_c). */
struct CeresCauchy
{
  swslam::graph::GraphOptimizerParams robust;
};

/** Optimizes a copy of `graph` with Ceres `repeats` times (the same residual as ours). */
swslam::bench::SolverRun runCeres(const swslam::graph::PoseGraph& graph, int repeats);
/** The same, with a Cauchy loss on the edges `cauchy` robustifies. */
swslam::bench::SolverRun runCeresWithLoss(const swslam::graph::PoseGraph& graph, int repeats,
                                          const std::optional<CeresCauchy>& cauchy);
