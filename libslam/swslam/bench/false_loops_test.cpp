// The false-loop benchmark measures what it says: least squares is pulled away by false loops
// and switches nothing off; graduated non-convexity, the adaptive kernel and truncated least
// squares switch off exactly the false loops and land on the outlier-free optimum.
#include <swslam/bench/false_loops.h>

#include <swslam/graph/synthetic.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::bench;

TEST(FalseLoops, EachMethodIsScoredAgainstTheOutlierFreeOptimum)
{
  graph::SyntheticGraphOptions o;
  o.nodes = 200;
  o.total_edges = 320;
  o.dense_neighbours = 0;
  o.seed = 4;
  const auto s = graph::makeGridWalkGraph(o);
  const auto cases = falseLoopCases("grid-200", s.graph, {0, 20}, graph::GraphOptimizerParams(),
                                    ourRobustMethods(graph::GraphOptimizerParams()));
  ASSERT_EQ(cases.size(), 3u * 5u);  // 0 loops; 20 random; 20 grouped: five methods each
  for (const FalseLoopCase& c : cases)
  {
    EXPECT_EQ(formatCase(c).rfind("grid-200", 0), 0u);
    if (c.method == "least-squares")
    {
      EXPECT_EQ(c.switched_off, 0u);
      if (c.false_loops == 0) EXPECT_LT(c.rmse_to_clean, 1e-6);
      if (c.false_loops > 0) EXPECT_GT(c.rmse_to_clean, 0.2) << formatCase(c);
    }
    if (c.method == "gnc" || c.method == "adaptive" || c.method == "tls")
    {
      EXPECT_LT(c.rmse_to_clean, 0.01) << formatCase(c);
      EXPECT_EQ(c.switched_off, c.false_loops) << formatCase(c);
      EXPECT_EQ(c.precision, 1.0) << formatCase(c);
      EXPECT_EQ(c.recall, 1.0) << formatCase(c);
      EXPECT_LT(std::abs(c.clean_chi2_excess), 1e-6) << formatCase(c);
    }
  }
}

TEST(FalseLoops, MethodsAreSelectedByName)
{
  const auto all = ourRobustMethods(graph::GraphOptimizerParams());
  const auto two = selectMethods(all, {"gnc", "least-squares"});
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].name, "least-squares");  // in the methods' own order
  EXPECT_EQ(two[1].name, "gnc");
  EXPECT_THROW(selectMethods(all, {"gnc", "gcn"}), std::invalid_argument);
}
