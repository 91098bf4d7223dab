#pragma once
// The pose-graph solvers compared by swslam-bench-graph: ours, MRPT's
// optimize_graph_spa_levmarq (L2 only) and Ceres (sparse normal Cholesky). Used by the
// benchmark only; Ceres is no dependency of the library.

#include <swslam/graph/optimizer_params.h>
#include <swslam/graph/pose_graph.h>

#include <string>

struct SolverRun
{
  std::string solver;
  double time_s = 0;       ///< median wall time over the repeats, problem set-up included
  double cpu_s = 0;        ///< median process CPU time (all threads): steadier on a busy machine
  size_t iterations = 0;
  swslam::graph::PoseGraph result;
};

SolverRun runOurs(const swslam::graph::PoseGraph& graph, const swslam::graph::GraphOptimizerParams& params,
                  int repeats);
SolverRun runMrpt(const swslam::graph::PoseGraph& graph, int repeats);
SolverRun runCeres(const swslam::graph::PoseGraph& graph, int repeats);

/** chi2 of `graph`'s poses with its original information matrices (our residual). */
double chi2Of(const swslam::graph::PoseGraph& graph);
