#pragma once
// The pose-graph solvers that swslam-bench-graph compares, run the same way: ours and MRPT's
// optimize_graph_spa_levmarq (L2 only), each timed over repeats; a third (Ceres, which the
// library does not depend on) plugs in as a GraphSolver.

#include <swslam/graph/optimizer_params.h>
#include <swslam/graph/pose_graph.h>

#include <functional>
#include <string>

namespace swslam::bench
{
struct SolverRun
{
  std::string solver;
  double time_s = 0;       ///< median wall time over the repeats, problem set-up included
  double cpu_s = 0;        ///< median process CPU time (all threads): steadier on a busy machine
  size_t iterations = 0;
  graph::PoseGraph result;
};

/** A solver: optimizes a copy of the graph `repeats` times and returns the last result. */
using GraphSolver = std::function<SolverRun(const graph::PoseGraph& graph, int repeats)>;

/** Median wall and CPU time of `repeats` calls of `run`, stored in `out`. */
void timeSolver(int repeats, const std::function<void()>& run, SolverRun& out);

SolverRun runOurs(const graph::PoseGraph& graph, const graph::GraphOptimizerParams& params, int repeats);
SolverRun runMrpt(const graph::PoseGraph& graph, int repeats);

/** chi2 of `graph`'s poses with its original information matrices (our residual). */
double chi2Of(const graph::PoseGraph& graph);

}  // namespace swslam::bench
