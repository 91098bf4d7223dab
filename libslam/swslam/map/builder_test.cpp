// MapBuilder. Eq. (15)-(16): a scan makes the cells its rays cross free and the cell at each
// ray's end occupied; repeated observations add up in log-odds. After an optimization, only
// the nodes that moved beyond the threshold are re-inserted. Moving a node removes its old
// contribution exactly: the map equals one built with the node at its new pose from the
// start, cell by cell, even where cells saturate. Readers only ever see whole updates.
#include <swslam/map/builder.h>
#include <swslam/map/scan_contribution.h>
#include <swslam/map/summed_grid.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose3D.h>

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "map_test_support.h"
#include "test_support.h"

using namespace swslam;
using namespace swslam::map;
using mrpt::poses::CPose2D;

namespace
{
/** p(occupied) of the cell containing (x, y). */
double occupancy(const mrpt::maps::COccupancyGridMap2D& g, double x, double y)
{
  return 1.0 - g.getPos(static_cast<float>(x), static_cast<float>(y));
}
}  // namespace

TEST(MapInsertion, RayCellsBecomeFreeAndItsEndOccupied)
{
  // Three rays over 180 deg: -90, 0, +90 deg. The middle one hits at 5 m along +x.
  MapBuilder map(test::smallMapParams(10));
  map.insert(0, test::makeScan({3.0, 5.0, 4.0}, M_PI), CPose2D(0.05, 0.05, 0));
  const auto g = map.snapshot();
  for (double x = 0.25; x < 4.9; x += 0.1) EXPECT_LT(occupancy(g, x, 0.05), 0.5) << x;
  EXPECT_GT(occupancy(g, 5.05, 0.05), 0.5);
  EXPECT_DOUBLE_EQ(occupancy(g, 5.55, 0.05), 0.5);  // beyond the hit: never observed
  EXPECT_GT(occupancy(g, 0.05, -2.95), 0.5);        // the -90 deg ray's end
  EXPECT_GT(occupancy(g, 0.05, 4.05), 0.5);         // the +90 deg ray's end
  EXPECT_DOUBLE_EQ(occupancy(g, -3, -3), 0.5);
}

TEST(MapInsertion, LeftToRightScansStartAtTheLeft)
{
  auto scan = test::makeScan({3.0, 5.0, 4.0}, M_PI);
  scan.rightToLeft = false;  // ray 0 at +90 deg, ray 2 at -90 deg
  MapBuilder map(test::smallMapParams(10));
  map.insert(0, scan, CPose2D(0.05, 0.05, 0));
  const auto g = map.snapshot();
  EXPECT_GT(occupancy(g, 0.05, 3.05), 0.5);
  EXPECT_GT(occupancy(g, 5.05, 0.05), 0.5);
  EXPECT_GT(occupancy(g, 0.05, -3.95), 0.5);
  EXPECT_DOUBLE_EQ(occupancy(g, 0.05, 4.05), 0.5);
}

TEST(MapInsertion, RepeatedHitsConvergeToOccupiedAndCrossedCellsToFree)
{
  MapBuilder map(test::smallMapParams(10));
  const auto scan = test::makeScan({2.0, 2.0, 2.0}, 0.02);
  double last_hit = 0.5, last_free = 0.5;
  for (MapNodeId k = 0; k < 30; k++)
  {
    map.insert(k, scan, CPose2D(0.05, 0.05, 0));
    const auto g = map.snapshot();
    const double hit = occupancy(g, 2.05, 0.05), free = occupancy(g, 1.05, 0.05);
    EXPECT_GE(hit, last_hit);
    EXPECT_LE(free, last_free);
    last_hit = hit, last_free = free;
  }
  EXPECT_GT(last_hit, 0.99);
  EXPECT_LT(last_free, 0.01);
}

TEST(MapInsertion, ContributionsAddUpInLogOddsAndClampOnlyInTheMirror)
{
  const auto p = test::smallMapParams(10);
  const auto c = computeContribution(sanitizedScan(test::makeScan({2.0, 2.0, 2.0}, 0.02), p),
                                     CPose2D(0.05, 0.05, 0), p);
  ASSERT_FALSE(c.runs.empty());
  SummedGrid grid(p.resolution, 5, 5);
  const int hx = cellOf(2.05, p.resolution), hy = cellOf(0.05, p.resolution);
  int32_t hit_delta = 0;
  for (const auto& run : c.runs)
    if (run.y == hy && hx >= run.x0 && hx < run.x0 + int(run.length))
      hit_delta = c.deltas[run.offset + (hx - run.x0)];
  ASSERT_LT(hit_delta, 0);  // MRPT's cells hold log-odds of "free": a hit is negative
  for (int k = 1; k <= 40; k++)
  {
    grid.add(c, +1);
    EXPECT_EQ(grid.sum(hx, hy), k * hit_delta);  // eq. (15), prior l(m) = 0
  }
  for (int k = 39; k >= 0; k--)
  {
    grid.add(c, -1);
    EXPECT_EQ(grid.sum(hx, hy), k * hit_delta);
  }
  for (auto v : grid.grid().getRawMap()) ASSERT_EQ(v, 0);
}

TEST(MapInsertion, OneNodeEqualsMrptInsertingIntoAnEmptyGrid)
{
  // The contribution machinery adds nothing of its own: one node gives MRPT's own result.
  const auto p = test::smallMapParams(10);
  std::mt19937 rng(3);
  const CPose2D pose(1.23, -0.4, 0.3);
  const auto obs = test::simulateObservation(test::roomWorld(), pose, 361, M_PI, 25, 0.01, rng);
  MapBuilder map(p);
  map.insert(7, obs, pose);
  mrpt::maps::COccupancyGridMap2D direct(-30, 30, -30, 30, static_cast<float>(p.resolution));
  direct.insertionOptions = insertionOptions(p);
  ASSERT_TRUE(direct.insertObservation(sanitizedScan(obs, p), mrpt::poses::CPose3D(pose)));
  const auto mine = map.snapshot();
  size_t touched = 0;
  for (auto v : direct.getRawMap()) touched += v != 0;
  ASSERT_GT(touched, 1000u);
  // Float cell lookups in grids of different origins may round a few border points apart.
  EXPECT_LE(test::differingCells(mine, direct), touched / 500);
}

TEST(MapInsertion, BadInputIsAClearError)
{
  MapBuilder map(test::smallMapParams(10));
  auto one_ray = test::makeScan({1.0}, 0.1);
  EXPECT_THROW(map.insert(0, one_ray, CPose2D()), std::invalid_argument);
  auto tilted = test::makeScan({1.0, 1.0, 1.0}, 1.0);
  tilted.sensorPose = mrpt::poses::CPose3D(0, 0, 0, 0, 0.2, 0);
  EXPECT_THROW(map.insert(0, tilted, CPose2D()), std::invalid_argument);
  EXPECT_THROW(map.insert(0, test::makeScan({1, 1}, 1.0), CPose2D(NAN, 0, 0)),
               std::invalid_argument);
  // NaN, negative and max-range readings flagged valid are dropped, not inserted.
  auto weird = test::makeScan({1.0, 1.0, 1.0, 1.0}, 1.0, 30);
  weird.setScanRange(0, NAN);
  weird.setScanRange(1, -2);
  weird.setScanRange(2, 30);
  EXPECT_NO_THROW(map.insert(1, weird, CPose2D()));
  map.insert(2, test::makeScan({1, 1}, 0.5), CPose2D());
  EXPECT_THROW(map.insert(2, test::makeScan({1, 1}, 0.5), CPose2D()), std::invalid_argument);
}

TEST(MapInsertion, GridGrowsToHoldFarScans)
{
  auto p = test::smallMapParams(10);
  p.initial_half_size = 2;
  p.grow_margin = 1;
  MapBuilder map(p);
  map.insert(0, test::makeScan({5.0, 5.0, 5.0}, 0.02), CPose2D(-40, 30, 0));
  const auto g = map.snapshot();
  EXPECT_LE(g.getXMin(), -41);
  EXPECT_GE(g.getYMax(), 31);
  EXPECT_GT(occupancy(g, -34.95, 30.05), 0.5);
  EXPECT_LT(occupancy(g, -37.05, 30.05), 0.5);
}

TEST(MapInsertion, AReusedScratchGridGivesTheSameContributions)
{
  // A long-range scan, then short ones at other poses, then the long one again: the scratch
  // grid kept from call to call (larger or smaller than needed, full of the previous scan)
  // changes no delta.
  const auto p = test::smallMapParams(10);
  std::vector<double> long_ranges(181, 25.0), short_ranges(181, 1.5);
  for (size_t i = 0; i < long_ranges.size(); i += 7) long_ranges[i] = -1;  // no return
  const auto far = sanitizedScan(test::makeScan(long_ranges, M_PI, 30), p);
  const auto near = sanitizedScan(test::makeScan(short_ranges, 1.5 * M_PI, 30), p);
  const std::vector<std::pair<const mrpt::obs::CObservation2DRangeScan*, CPose2D>> calls = {
      {&far, CPose2D(0.05, 0.05, 0.3)},   {&near, CPose2D(-3.1, 7.2, -2.0)},
      {&near, CPose2D(40.0, -12.0, 1.0)}, {&far, CPose2D(0.05, 0.05, 0.3)},
      {&far, CPose2D(-55.3, 20.1, 3.0)}};
  ContributionScratch scratch;
  for (const auto& [scan, pose] : calls)
  {
    test::expectSameContribution(computeContribution(*scan, pose, p, scratch), computeContribution(*scan, pose, p));
  }
}

TEST(MapReinsert, OnlyMovedNodesAreTouched)
{
  MapParams p;
  p.resolution = 0.1;
  p.initial_half_size = 15;
  const geometry::MoveThreshold t{0.1, mrpt::DEG2RAD(1.0)};
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
