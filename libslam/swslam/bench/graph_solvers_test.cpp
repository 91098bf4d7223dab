// The benchmark's solvers: ours and MRPT's reach the same least-squares optimum on a small
// grid walk, each timed; the benchmark's graphs are what their names say.
#include <swslam/bench/graph.h>
#include <swslam/bench/graph_solvers.h>

#include <gtest/gtest.h>

using namespace swslam;
using namespace swslam::bench;

TEST(GraphSolvers, OursAndMrptReachTheSameLeastSquaresOptimum)
{
  const BenchGraph g = gridGraph(60, 180, 1, 4, 0, 5);
  graph::GraphOptimizerParams l2;
  l2.kernel_alpha = 2;
  const SolverRun ours = runOurs(g.graph, l2, 2);
  const SolverRun mrpt = runMrpt(g.graph, 1);
  EXPECT_EQ(ours.solver, "swslam");
  EXPECT_EQ(mrpt.solver, "mrpt-levmarq");
  const double start = chi2Of(g.graph);
  EXPECT_LT(chi2Of(ours.result), 0.5 * start);
  EXPECT_NEAR(chi2Of(ours.result), chi2Of(mrpt.result), 1e-3 * chi2Of(mrpt.result) + 1e-9);
  EXPECT_GT(ours.time_s, 0);
  EXPECT_GT(ours.iterations, 0u);
  EXPECT_EQ(chi2Of(g.graph), start) << "the input graph is not touched";
}

TEST(GraphSolvers, AGridGraphIsNamedByItsSize)
{
  const BenchGraph g = gridGraph(60, 180, 1, 4, 0, 5);
  EXPECT_EQ(g.graph.nodeCount(), 60u);
  EXPECT_EQ(g.name.rfind("grid-60n-" + std::to_string(g.graph.edgeCount()) + "e-", 0), 0u) << g.name;
  EXPECT_EQ(g.truth.size(), 60u);
}
