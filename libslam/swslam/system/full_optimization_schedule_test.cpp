// When the graph module optimizes the whole graph: after every loop with interval 1; with a
// longer interval, loops that come node after node share one full optimization per interval,
// and none is lost.
#include <swslam/system/full_optimization_schedule.h>

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <vector>

namespace
{
/** The nodes that get a full optimization, for nodes 0..n-1 with loops at `loop_nodes`. */
std::vector<size_t> fullNodes(size_t interval, size_t n, const std::set<size_t>& loop_nodes)
{
  swslam::system::FullOptimizationSchedule s(interval);
  std::vector<size_t> full;
  for (size_t id = 0; id < n; ++id)
    if (s.fullNow(id, loop_nodes.count(id))) full.push_back(id);
  return full;
}
}  // namespace

TEST(FullOptimizationSchedule, IntervalOneOptimizesAfterEveryLoop)
{
  EXPECT_EQ(fullNodes(1, 50, {10, 11, 12, 30}), (std::vector<size_t>{10, 11, 12, 30}));
  EXPECT_TRUE(fullNodes(1, 50, {}).empty());
}

TEST(FullOptimizationSchedule, ARunOfLoopsSharesOneFullOptimizationPerInterval)
{
  // The first loop at once; 11-14 wait; 15 runs the pending one although it closes no loop
  // itself; 16-19 wait for 20, which closes none either; then nothing is pending.
  EXPECT_EQ(fullNodes(5, 40, {10, 11, 12, 13, 14, 16, 18}), (std::vector<size_t>{10, 15, 20}));
  // A loop long after the last full optimization is optimized at once.
  EXPECT_EQ(fullNodes(5, 60, {10, 12, 40}), (std::vector<size_t>{10, 15, 40}));
  // Loops on every node of a long run: one full optimization per interval, and the loops of
  // 121-129 get theirs at 130.
  std::set<size_t> every;
  for (size_t id = 100; id < 130; ++id) every.insert(id);
  EXPECT_EQ(fullNodes(10, 140, every), (std::vector<size_t>{100, 110, 120, 130}));
}

TEST(FullOptimizationSchedule, ARunOutsideTheScheduleClearsWhatIsPending)
{
  swslam::system::FullOptimizationSchedule s(5);
  EXPECT_TRUE(s.fullNow(3, 1));
  EXPECT_FALSE(s.fullNow(4, 2));
  EXPECT_TRUE(s.pending());
  s.ranFull(6);  // e.g. the end of a run
  EXPECT_FALSE(s.pending());
  EXPECT_FALSE(s.fullNow(8, 0));
  EXPECT_FALSE(s.fullNow(9, 1));   // within 5 nodes of 6: waits
  EXPECT_TRUE(s.fullNow(11, 0));   // 6 + 5
}

TEST(FullOptimizationSchedule, ZeroIntervalIsAnError)
{
  EXPECT_THROW(swslam::system::FullOptimizationSchedule(0), std::invalid_argument);
}

TEST(FullOptimizationSchedule, OnlyALoopThatDisagreesWithTheGraphCorrectsIt)
{
  using mrpt::poses::CPose2D;
  const CPose2D graph(3.0, 1.0, 0.4);  // newer node in the older node's frame, per the graph
  const double xy = 0.05, theta = 0.5 * M_PI / 180;
  // The measurement is the graph's relative pose moved by d, in the newer node's frame.
  auto measured = [&](double dx, double dy, double dphi) { return graph + CPose2D(dx, dy, dphi); };
  EXPECT_FALSE(swslam::system::loopCorrectsGraph(graph, graph, xy, theta));
  EXPECT_FALSE(swslam::system::loopCorrectsGraph(graph, measured(0.03, -0.02, 0.005), xy, theta));
  EXPECT_TRUE(swslam::system::loopCorrectsGraph(graph, measured(0.04, -0.04, 0.0), xy, theta));  // 5.7 cm
  EXPECT_TRUE(swslam::system::loopCorrectsGraph(graph, measured(0.0, 0.0, -0.01), xy, theta));   // 0.57 deg
  // Headings on either side of +-180 deg differ by their wrapped difference.
  EXPECT_FALSE(swslam::system::loopCorrectsGraph(CPose2D(1, 2, M_PI - 0.001), CPose2D(1, 2, -M_PI + 0.001),
                                         xy, theta));
  EXPECT_TRUE(swslam::system::loopCorrectsGraph(CPose2D(1, 2, M_PI - 0.01), CPose2D(1, 2, -M_PI + 0.01),
                                        xy, theta));
  // Zero thresholds: every loop corrects the graph, even one that agrees exactly (the paper).
  EXPECT_TRUE(swslam::system::loopCorrectsGraph(graph, measured(1e-6, 0, 0), 0, 0));
  EXPECT_TRUE(swslam::system::loopCorrectsGraph(graph, graph, 0, 0));
  // One zero threshold alone: any difference in that component counts.
  EXPECT_TRUE(swslam::system::loopCorrectsGraph(graph, measured(0, 0, 1e-6), xy, 0));
  EXPECT_FALSE(swslam::system::loopCorrectsGraph(graph, graph, xy, 0));
}
