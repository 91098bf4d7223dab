#include <swslam/localize/map_score_grid.h>

#include <gtest/gtest.h>

using namespace swslam;

namespace
{
/** A 10 x 10 m grid: a wall of occupied cells along x = 2, free cells left of it, the rest unknown. */
mrpt::maps::COccupancyGridMap2D wallGrid()
{
  mrpt::maps::COccupancyGridMap2D g(-5, 5, -5, 5, 0.2f);
  for (unsigned y = 0; y < g.getSizeY(); ++y)
    for (unsigned x = 0; x < g.getSizeX(); ++x)
    {
      const double cx = g.idx2x(x);
      // setCell takes p(free).
      if (std::abs(cx - 2.1) < 0.1) g.setCell(x, y, 0.05f);
      else if (cx < 2) g.setCell(x, y, 0.95f);
    }
  return g;
}
}  // namespace

TEST(MapScoreGrid, OccupiedCellsAreTheWall)
{
  const auto cells = localize::occupiedCells(wallGrid(), 0.65);
  ASSERT_EQ(cells.size(), 50u);
  for (const auto& c : cells) EXPECT_NEAR(c.x(), 2.1, 1e-6);
}

TEST(MapScoreGrid, PeaksOnTheWallNegativeOnFreeZeroOnUnknown)
{
  const auto g = localize::occupancyScoreGrid(wallGrid(), 0.65, 0.196, 0.2, -255, 3);
  ASSERT_FALSE(g.cells.empty());
  EXPECT_EQ(g.pad_cells, 3);
  auto at = [&](double x, double y) {
    const Eigen::Vector2i c = g.cellOf({x, y});
    return g.at(c.x(), c.y());
  };
  EXPECT_GT(at(2.1, 0.1), 240);
  EXPECT_GT(at(1.9, 0.1), 0);    // the kernel reaches one cell into free space
  EXPECT_EQ(at(-3.0, 0.1), -255);  // free, far from the wall
  EXPECT_EQ(at(4.5, 0.1), 0);    // unknown, beyond the kernel
}

TEST(MapScoreGrid, AMapWithNoObstacleGivesAnEmptyGrid)
{
  mrpt::maps::COccupancyGridMap2D g(-5, 5, -5, 5, 0.2f);
  EXPECT_TRUE(localize::occupancyScoreGrid(g, 0.65, 0.196, 0.2, -255, 3).cells.empty());
}
