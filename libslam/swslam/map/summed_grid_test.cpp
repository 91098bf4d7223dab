// The tiled sums of SummedGrid against a plain map of cell -> sum: random contributions at
// negative and positive cells, across tile borders, that make the grid grow on every side.
#include <swslam/map/summed_grid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace
{
using swslam::map::CellBox;
using swslam::map::ScanContribution;
using swslam::map::SummedGrid;
using swslam::map::SumsChange;
using Grid = mrpt::maps::COccupancyGridMap2D;

/** A contribution of random runs in the cell box [x0, x0 + w) x [y0, y0 + h). */
ScanContribution randomContribution(std::mt19937& rng, int x0, int y0, int w, int h)
{
  std::uniform_int_distribution<int> delta(-60, 40), coin(0, 3);
  ScanContribution c;
  c.box = CellBox{INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN};
  for (int y = y0; y < y0 + h; y++)
  {
    if (coin(rng) == 0) continue;  // rows without a run
    const int a = std::uniform_int_distribution<int>(x0, x0 + w - 1)(rng);
    const int b = std::uniform_int_distribution<int>(a, x0 + w - 1)(rng);
    c.runs.push_back({y, a, static_cast<uint32_t>(c.deltas.size()), static_cast<uint32_t>(b - a + 1)});
    for (int x = a; x <= b; x++) c.deltas.push_back(static_cast<ScanContribution::Delta>(delta(rng)));
    c.box = CellBox{std::min(c.box.x0, a), std::min(c.box.y0, y), std::max(c.box.x1, b + 1),
                    std::max(c.box.y1, y + 1)};
  }
  if (c.runs.empty()) c.box = CellBox{};
  return c;
}

void addTo(std::map<std::pair<int, int>, int32_t>& sums, const ScanContribution& c, int sign)
{
  for (const auto& run : c.runs)
    for (uint32_t k = 0; k < run.length; k++)
      sums[{run.x0 + static_cast<int>(k), run.y}] += sign * c.deltas[run.offset + k];
}

/** Every cell of the grid's box: the sum equals the reference's, and the MRPT cell its clamp. */
void expectEqual(const SummedGrid& grid, const std::map<std::pair<int, int>, int32_t>& sums)
{
  const CellBox& b = grid.box();
  ASSERT_EQ(static_cast<int>(grid.grid().getSizeX()), b.width());
  ASSERT_EQ(static_cast<int>(grid.grid().getSizeY()), b.height());
  for (const auto& [cell, s] : sums)
    ASSERT_TRUE(cell.first >= b.x0 && cell.first < b.x1 && cell.second >= b.y0 && cell.second < b.y1)
        << "cell " << cell.first << "," << cell.second << " outside the grid";
  for (int y = b.y0; y < b.y1; y++)
  {
    const Grid::cellType* row = grid.grid().getRow(y - b.y0);
    for (int x = b.x0; x < b.x1; x++)
    {
      const auto it = sums.find({x, y});
      const int32_t expected = it == sums.end() ? 0 : it->second;
      ASSERT_EQ(grid.sum(x, y), expected) << "cell " << x << "," << y;
      ASSERT_EQ(row[x - b.x0], std::clamp<int32_t>(expected, Grid::OCCGRID_CELLTYPE_MIN,
                                                   Grid::OCCGRID_CELLTYPE_MAX))
          << "cell " << x << "," << y;
    }
  }
}
}  // namespace

TEST(SummedGrid, TiledSumsEqualAPlainSumThroughGrowthOnEverySide)
{
  std::mt19937 rng(17);
  const double res = 0.5;
  SummedGrid grid(res, 10, 5);  // cells [-20, 20)^2, grows by 10 cells
  std::map<std::pair<int, int>, int32_t> sums;
  std::vector<ScanContribution> added;
  // Boxes inside, then across tile borders (multiples of 64), then beyond each side.
  const std::vector<CellBox> places = {{-15, -15, 15, 15},  {-70, -10, -50, 30}, {60, 60, 140, 75},
                                       {-200, -130, -120, -60}, {100, -300, 180, -250},
                                       {-5, 250, 70, 330},    {-64, -64, 64, 64}};
  for (int round = 0; round < 3; round++)
    for (const CellBox& p : places)
    {
      const ScanContribution c = randomContribution(rng, p.x0, p.y0, p.width(), p.height());
      grid.add(c, +1);
      addTo(sums, c, +1);
      added.push_back(c);
    }
  EXPECT_LE(grid.box().x0, -200);
  EXPECT_GE(grid.box().x1, 180);
  EXPECT_LE(grid.box().y0, -300);
  EXPECT_GE(grid.box().y1, 330);
  expectEqual(grid, sums);
  EXPECT_GT(grid.tileCount(), 10u);
  // Fewer tiles than a dense grid would need.
  const CellBox& b = grid.box();
  EXPECT_LT(grid.tileCount(), static_cast<size_t>(b.width() / 64 + 2) * (b.height() / 64 + 2));

  // Saturate some cells well beyond the 8-bit range, then take half of everything out.
  for (int k = 0; k < 6; k++)
  {
    grid.add(added[k % 3], +1);
    addTo(sums, added[k % 3], +1);
  }
  for (size_t k = 0; k < added.size(); k += 2)
  {
    grid.add(added[k], -1);
    addTo(sums, added[k], -1);
  }
  expectEqual(grid, sums);

  // And the rest: every sum back to zero, every cell back to 0.5.
  for (int k = 0; k < 6; k++) grid.add(added[k % 3], -1);
  for (size_t k = 1; k < added.size(); k += 2) grid.add(added[k], -1);
  for (auto v : grid.grid().getRawMap()) ASSERT_EQ(v, 0);
  for (int y = grid.box().y0; y < grid.box().y1; y += 7)
    for (int x = grid.box().x0; x < grid.box().x1; x += 7) ASSERT_EQ(grid.sum(x, y), 0);
}

TEST(SummedGrid, AChangeAppliedAtOnceEqualsItsContributionsAddedOneByOne)
{
  std::mt19937 rng(23);
  const double res = 0.5;
  SummedGrid one_by_one(res, 10, 5), at_once(res, 10, 5);
  std::vector<ScanContribution> before;
  for (const CellBox& p : std::vector<CellBox>{{-15, -15, 15, 15}, {-70, -10, -50, 30}})
  {
    before.push_back(randomContribution(rng, p.x0, p.y0, p.width(), p.height()));
    one_by_one.add(before.back(), +1);
    at_once.add(before.back(), +1);
  }
  // Out with the first, in with new ones beyond two sides (the grid grows for each in turn),
  // out with the second: as an optimization's re-insertion does.
  SumsChange change;
  std::map<std::pair<int, int>, int32_t> sums;
  addTo(sums, before[1], +1);
  one_by_one.add(before[0], -1);
  change.add(before[0], -1);
  for (const CellBox& p : std::vector<CellBox>{{60, 60, 140, 75}, {-200, -130, -120, -60}, {-5, 250, 70, 330}})
  {
    const ScanContribution c = randomContribution(rng, p.x0, p.y0, p.width(), p.height());
    one_by_one.add(c, +1);
    change.add(c, +1);
    addTo(sums, c, +1);
  }
  one_by_one.add(before[1], -1);
  change.add(before[1], -1);
  addTo(sums, before[1], -1);
  EXPECT_FALSE(change.empty());
  EXPECT_GT(change.bytes(), 0u);
  at_once.apply(change);
  EXPECT_EQ(at_once.box().x0, one_by_one.box().x0);
  EXPECT_EQ(at_once.box().y0, one_by_one.box().y0);
  EXPECT_EQ(at_once.box().x1, one_by_one.box().x1);
  EXPECT_EQ(at_once.box().y1, one_by_one.box().y1);
  expectEqual(at_once, sums);
  expectEqual(one_by_one, sums);
}

TEST(SummedGrid, OutsideTheGridTheSumIsZeroAndABadSignIsAnError)
{
  SummedGrid grid(0.2, 4, 4);
  EXPECT_EQ(grid.sum(1000, -1000), 0);
  EXPECT_EQ(grid.sum(0, 0), 0);
  EXPECT_EQ(grid.tileCount(), 0u);
  std::mt19937 rng(3);
  const ScanContribution c = randomContribution(rng, -5, -5, 10, 10);
  EXPECT_THROW(grid.add(c, 2), std::invalid_argument);
  EXPECT_THROW(SummedGrid(0, 4, 4), std::invalid_argument);
  // Checked before any length becomes a cell count (an int).
  EXPECT_THROW(SummedGrid(0.2, std::numeric_limits<double>::infinity(), 4), std::invalid_argument);
  EXPECT_THROW(SummedGrid(0.2, 4, std::nan("")), std::invalid_argument);
  EXPECT_THROW(SummedGrid(1e-9, 4, 4), std::invalid_argument);
  EXPECT_THROW(SummedGrid(0.2, 4, -1), std::invalid_argument);
}

TEST(SummedGrid, AGrowthBeyondTheCellLimitIsRefusedAndLeavesTheMapAsItWas)
{
  // A node whose pose is far off (bad odometry) would grow the map by millions of cells a side.
  SummedGrid grid(0.2, 4, 4);
  std::mt19937 rng(5);
  const ScanContribution near = randomContribution(rng, -5, -5, 10, 10);
  grid.add(near, +1);
  const CellBox before = grid.box();
  const int far = static_cast<int>(swslam::map::kMaxMapCells / 30);  // 30 cells tall: just over the limit
  const ScanContribution off = randomContribution(rng, far, -5, 10, 10);
  try
  {
    grid.add(off, +1);
    FAIL() << "the growth must be refused";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("over the limit"), std::string::npos) << e.what();
  }
  EXPECT_EQ(grid.box().x1, before.x1);
  EXPECT_EQ(static_cast<int>(grid.grid().getSizeX()), before.width());
  grid.add(near, -1);  // still consistent: back to all zero
  for (auto v : grid.grid().getRawMap()) ASSERT_EQ(v, 0);
}
