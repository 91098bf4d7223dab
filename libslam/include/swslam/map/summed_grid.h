#pragma once
// The map as the sum of its nodes' contributions (eq. 15 with a 0.5 prior): exact integer
// sums per cell, mirrored into an MRPT occupancy grid clamped to its cell range. Adding then
// subtracting a contribution restores every cell exactly, saturated or not.

#include <swslam/map/scan_contribution.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <vector>

namespace swslam
{
class SummedGrid
{
 public:
  /** Empty map covering [-half_size, half_size]^2; grows by `grow_margin` [m] beyond any
   * contribution that leaves it. */
  SummedGrid(double resolution, double half_size, double grow_margin);

  /** Adds `sign` (+1 or -1) times `c` to the sums and refreshes the mirrored cells. */
  void add(const ScanContribution& c, int sign);

  const mrpt::maps::COccupancyGridMap2D& grid() const { return grid_; }
  const CellBox& box() const { return box_; }
  /** Sum of the deltas at global cell (x, y); 0 outside the grid. */
  int32_t sum(int x, int y) const;
  size_t bytes() const { return sums_.size() * sizeof(int32_t) + grid_.getRawMap().size(); }

 private:
  void growToContain(const CellBox& b);
  void mirrorRow(int y, int x0, int x1);

  double resolution_;
  int margin_cells_;
  CellBox box_;                  ///< global cells covered by sums_ and grid_
  std::vector<int32_t> sums_;    ///< row-major over box_
  mrpt::maps::COccupancyGridMap2D grid_;  ///< clamp(sums_), same layout
};

}  // namespace swslam
