// After an optimization, only the nodes that moved beyond the threshold are re-inserted.
#include "map_test_support.h"
#include "test_support.h"

#include <swslam/map/map_builder.h>

#include <mrpt/core/bits_math.h>

#include <gtest/gtest.h>

using namespace swslam;
using mrpt::poses::CPose2D;

TEST(MapReinsert, MovedBeyondTranslationOrRotation)
{
  const MoveThreshold t{0.1, mrpt::DEG2RAD(1.0)};
  EXPECT_FALSE(movedBeyond(CPose2D(1, 2, 0.3), CPose2D(1.05, 2.05, 0.3), t));
  EXPECT_TRUE(movedBeyond(CPose2D(1, 2, 0.3), CPose2D(1.08, 2.08, 0.3), t));
  EXPECT_FALSE(movedBeyond(CPose2D(0, 0, 0), CPose2D(0, 0, mrpt::DEG2RAD(0.9)), t));
  EXPECT_TRUE(movedBeyond(CPose2D(0, 0, 0), CPose2D(0, 0, mrpt::DEG2RAD(1.1)), t));
  // Angles wrap: 179.8 deg and -179.8 deg are 0.4 deg apart.
  EXPECT_FALSE(movedBeyond(CPose2D(0, 0, mrpt::DEG2RAD(179.8)), CPose2D(0, 0, mrpt::DEG2RAD(-179.8)), t));
}

TEST(MapReinsert, OnlyMovedNodesAreTouched)
{
  MapParams p;
  p.resolution = 0.1;
  p.initial_half_size = 15;
  const MoveThreshold t{0.1, mrpt::DEG2RAD(1.0)};
  std::vector<CPose2D> at = {{-6, 0, 0}, {-3, 1, 0.5}, {0, 0, 1}, {3, -1, 1.5}, {6, 0, 2}};
  std::vector<mrpt::obs::CObservation2DRangeScan> scans;
  MapBuilder m(p);
  for (size_t k = 0; k < at.size(); k++)
  {
    std::mt19937 rng(k);
    scans.push_back(test::simulateObservation(test::roomWorld(), at[k], 361, 1.5 * M_PI, 30, 0.02, rng));
    m.insert(k, scans[k], at[k]);
  }
  std::map<MapNodeId, CPose2D> optimized = {
      {0, CPose2D(-6, 0, 0)},                      // unchanged
      {1, CPose2D(-2.7, 1.1, 0.5)},                // moved 0.32 m
      {2, CPose2D(0.03, 0.02, 1)},                 // below the threshold
      {3, CPose2D(3, -1, 1.5 + mrpt::DEG2RAD(3))}, // turned 3 deg
      {99, CPose2D(1, 1, 1)},                      // not in the map
  };
  const auto r = m.reinsertMoved(optimized, t);
  EXPECT_EQ(r.moved, 2u);
  EXPECT_EQ(r.unchanged, 2u);
  EXPECT_EQ(r.unknown, 1u);
  EXPECT_EQ(m.nodePose(1), optimized[1]);
  EXPECT_EQ(m.nodePose(2), at[2]);  // kept at its inserted pose
  EXPECT_EQ(m.nodePose(3), optimized[3]);
  EXPECT_EQ(m.nodePose(4), at[4]);  // not given: untouched

  // The map is the one built with the poses each node now holds.
  MapBuilder fresh(p);
  for (size_t k = 0; k < at.size(); k++) fresh.insert(k, scans[k], m.nodePose(k));
  EXPECT_EQ(test::differingCells(m.snapshot(), fresh.snapshot()), 0u);

  // A second pass with the same poses moves nothing.
  const auto again = m.reinsertMoved(optimized, t);
  EXPECT_EQ(again.moved, 0u);
  EXPECT_THROW(m.reinsertMoved({{1, CPose2D(NAN, 0, 0)}}, t), std::invalid_argument);
}
