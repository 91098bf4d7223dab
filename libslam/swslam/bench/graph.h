#pragma once
// The pose-graph optimizer's benchmark (swslam-bench-graph, doc/graph-optimization.md): ours
// vs MRPT's optimize_graph_spa_levmarq vs Ceres on the same graphs (time,
// final chi2 with the original information, error vs truth), the sliding-window update cost
// against graph size, and robust vs L2 under wrong loops. Prints its tables to stdout.

#include <swslam/bench/graph_solvers.h>
#include <swslam/geometry/se2_error.h>
#include <swslam/graph/pose_graph.h>

#include <string>
#include <vector>

namespace swslam::bench
{
struct BenchGraph
{
  std::string name;
  graph::PoseGraph graph;
  std::vector<geometry::Pose2> truth;  ///< empty if unknown
};

/** Grid walk of `nodes` in a (2 extent + 1)^2 m area; `dense` earlier nodes linked to each
 * node besides its predecessor, loops up to `edges` in total, `wrong` share of wrong loops. */
BenchGraph gridGraph(size_t nodes, size_t edges, size_t dense, int extent, double wrong, unsigned seed);

/** Runs every section: `run_ceres` runs Ceres (which the library does not link; empty: the
 * first table compares with MRPT only). Throws
 * std::runtime_error if MRPT's circle graph is not in `mrpt_datasets`. */
void runGraphBenchmark(const std::string& mrpt_datasets, int repeats, const GraphSolver& run_ceres);

}  // namespace swslam::bench
