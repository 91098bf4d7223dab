// Moving a node removes its old contribution exactly: the map equals one built with the
// node at its new pose from the start, cell by cell, even where cells saturate.
#include "map_test_support.h"
#include "test_support.h"

#include <swslam/map/map_builder.h>

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

using namespace swslam;
using mrpt::poses::CPose2D;

namespace
{
MapParams params()
{
  auto p = test::smallMapParams(5);
  p.grow_margin = 2;
  return p;
}

mrpt::obs::CObservation2DRangeScan roomScan(const CPose2D& pose, unsigned seed)
{
  std::mt19937 rng(seed);
  return test::simulateObservation(test::roomWorld(), pose, 541, 1.5 * M_PI, 30, 0.02, rng);
}
}  // namespace

TEST(MapUpdate, UpdateEqualsInsertingAtTheNewPoseDirectly)
{
  const CPose2D p1(-3, 1, 0.2), p2(-2.4, 1.3, 0.35);  // far enough to touch other cells
  const auto a = roomScan(p2, 1);
  MapBuilder moved(params()), direct(params());
  moved.insert(0, a, p1);
  moved.update(0, p2);
  direct.insert(0, a, p2);
  EXPECT_EQ(test::differingCells(moved.snapshot(), direct.snapshot()), 0u);
  EXPECT_EQ(moved.nodePose(0), p2);
}

TEST(MapUpdate, ExactAmongOtherNodesAndSaturatedCells)
{
  // Nodes b and c are inserted 12 times each at the same poses so that many cells reach
  // the grid's log-odds bound; a is then moved. A clamped in-place grid could not undo a's
  // old contribution there; the summed grid can.
  const CPose2D pa1(0, 0, 0), pa2(1.1, -0.7, -0.4), pb(2, 1, 1.0), pc(-4, -2, 2.5);
  auto build = [&](bool move) {
    MapBuilder m(params());
    m.insert(100, roomScan(pa1, 7), move ? pa1 : pa2);
    for (MapNodeId k = 0; k < 12; k++)
    {
      m.insert(k, roomScan(pb, 8), pb);
      m.insert(20 + k, roomScan(pc, 9), pc);
    }
    if (move) m.update(100, pa2);
    return m.snapshot();
  };
  const auto moved = build(true), direct = build(false);
  size_t saturated = 0;
  for (auto v : direct.getRawMap())
    saturated += v == mrpt::maps::COccupancyGridMap2D::OCCGRID_CELLTYPE_MIN ||
                 v == mrpt::maps::COccupancyGridMap2D::OCCGRID_CELLTYPE_MAX;
  ASSERT_GT(saturated, 100u);
  EXPECT_EQ(test::differingCells(moved, direct), 0u);
}

TEST(MapUpdate, RemovingEveryNodeLeavesAnUnobservedGrid)
{
  MapBuilder m(params());
  for (MapNodeId k = 0; k < 4; k++) m.insert(k, roomScan(CPose2D(k, 0.5 * k, 0.3 * k), k), CPose2D(k, 0.5 * k, 0.3 * k));
  m.update(2, CPose2D(-6, -3, 1));  // also grows the grid
  for (MapNodeId k = 0; k < 4; k++) m.remove(k);
  EXPECT_EQ(m.nodeCount(), 0u);
  const auto g = m.snapshot();
  for (auto v : g.getRawMap()) ASSERT_EQ(v, 0);
  EXPECT_THROW(m.remove(0), std::invalid_argument);
  EXPECT_THROW(m.update(0, CPose2D()), std::invalid_argument);
}

TEST(MapUpdate, ReadersOnlyEverSeeWholeUpdates)
{
  const CPose2D p1(-3, 1, 0.2), p2(2, -1, -0.5);
  const auto a = roomScan(p1, 3), b = roomScan(p2, 4);
  auto reference = [&](const CPose2D& pose_a) {
    MapBuilder m(params());
    m.insert(0, a, pose_a);
    m.insert(1, b, p2);
    return m.snapshot();
  };
  const auto at1 = reference(p1), at2 = reference(p2);
  MapBuilder m(params());
  m.insert(0, a, p1);
  m.insert(1, b, p2);
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (int i = 0; i < 30; i++) m.update(0, i % 2 ? p1 : p2);
    done = true;
  });
  size_t seen = 0;
  while (!done || seen < 5)
  {
    const auto s = m.snapshot();
    ASSERT_TRUE(test::differingCells(s, at1) == 0 || test::differingCells(s, at2) == 0);
    seen++;
  }
  writer.join();
  EXPECT_EQ(test::differingCells(m.snapshot(), at1), 0u);
}
