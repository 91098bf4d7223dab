// Eq. (15)-(16): a scan makes the cells its rays cross free and the cell at each ray's end
// occupied; repeated observations add up in log-odds.
#include "map_test_support.h"
#include "test_support.h"

#include <swslam/map/map_builder.h>
#include <swslam/map/scan_contribution.h>
#include <swslam/map/summed_grid.h>

#include <mrpt/poses/CPose3D.h>

#include <gtest/gtest.h>

using namespace swslam;
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
  direct.insertionOptions = p.insertionOptions();
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
    const ScanContribution reused = computeContribution(*scan, pose, p, scratch);
    const ScanContribution fresh = computeContribution(*scan, pose, p);
    ASSERT_FALSE(fresh.runs.empty());
    ASSERT_EQ(reused.runs.size(), fresh.runs.size());
    for (size_t k = 0; k < fresh.runs.size(); k++)
    {
      EXPECT_EQ(reused.runs[k].y, fresh.runs[k].y);
      EXPECT_EQ(reused.runs[k].x0, fresh.runs[k].x0);
      EXPECT_EQ(reused.runs[k].length, fresh.runs[k].length);
    }
    EXPECT_EQ(reused.deltas, fresh.deltas);
  }
}
