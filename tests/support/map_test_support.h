#pragma once
// Helpers shared by the map tests: hand-made scans and cell-by-cell grid comparison.

#include <swslam/map/params.h>
#include <swslam/map/scan_contribution.h>

#include <gtest/gtest.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <vector>

namespace swslam::test
{
/** Map parameters for small synthetic worlds: 0.1 m cells, a grid of +-half_size m. */
inline map::MapParams smallMapParams(double half_size)
{
  map::MapParams p;
  p.resolution = 0.1;
  p.initial_half_size = half_size;
  return p;
}

/** A scan of `ranges.size()` rays over `aperture`; negative ranges are "no return". */
inline mrpt::obs::CObservation2DRangeScan makeScan(const std::vector<double>& ranges,
                                                   double aperture, double max_range = 30)
{
  mrpt::obs::CObservation2DRangeScan obs;
  obs.sensorLabel = "LASER";
  obs.aperture = static_cast<float>(aperture);
  obs.maxRange = static_cast<float>(max_range);
  obs.rightToLeft = true;
  obs.resizeScan(ranges.size());
  for (size_t i = 0; i < ranges.size(); i++)
  {
    obs.setScanRange(i, static_cast<float>(ranges[i] < 0 ? max_range : ranges[i]));
    obs.setScanRangeValidity(i, ranges[i] >= 0);
  }
  return obs;
}

/** Number of cells whose raw log-odds differ between `a` and `b` (same resolution), over
 * the union of both grids; a cell outside a grid counts as 0 (unobserved). */
inline size_t differingCells(const mrpt::maps::COccupancyGridMap2D& a,
                             const mrpt::maps::COccupancyGridMap2D& b)
{
  const double res = a.getResolution();
  auto origin = [res](const mrpt::maps::COccupancyGridMap2D& g) {
    return std::make_pair(static_cast<int>(std::lround(g.getXMin() / res)),
                          static_cast<int>(std::lround(g.getYMin() / res)));
  };
  auto at = [&](const mrpt::maps::COccupancyGridMap2D& g, int x, int y) -> int {
    const auto [ox, oy] = origin(g);
    const int cx = x - ox, cy = y - oy;
    if (cx < 0 || cy < 0 || cx >= int(g.getSizeX()) || cy >= int(g.getSizeY())) return 0;
    return g.getRawMap()[size_t(cy) * g.getSizeX() + cx];
  };
  const auto [ax, ay] = origin(a);
  const auto [bx, by] = origin(b);
  const int x0 = std::min(ax, bx), y0 = std::min(ay, by);
  const int x1 = std::max(ax + int(a.getSizeX()), bx + int(b.getSizeX()));
  const int y1 = std::max(ay + int(a.getSizeY()), by + int(b.getSizeY()));
  size_t n = 0;
  for (int y = y0; y < y1; y++)
    for (int x = x0; x < x1; x++) n += at(a, x, y) != at(b, x, y);
  return n;
}

/** `a` has the runs (row, first cell, length) and deltas of `b`, which is not empty. */
inline void expectSameContribution(const map::ScanContribution& a, const map::ScanContribution& b)
{
  ASSERT_FALSE(b.runs.empty());
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (size_t k = 0; k < b.runs.size(); k++)
  {
    EXPECT_EQ(a.runs[k].y, b.runs[k].y) << "run " << k;
    EXPECT_EQ(a.runs[k].x0, b.runs[k].x0) << "run " << k;
    EXPECT_EQ(a.runs[k].length, b.runs[k].length) << "run " << k;
  }
  EXPECT_EQ(a.deltas, b.deltas);
}

}  // namespace swslam::test
