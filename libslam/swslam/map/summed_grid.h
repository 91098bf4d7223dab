#pragma once
// The map as the sum of its nodes' contributions (eq. 15 with a 0.5 prior): exact integer
// sums per cell, mirrored into an MRPT occupancy grid clamped to its cell range. Adding then
// subtracting a contribution restores every cell exactly, saturated or not.
//
// The sums are kept in square tiles, allocated when a contribution first touches them, so
// that growing the map never copies them: a growth re-indexes the tiles and re-sizes the
// MRPT grid only (on the valley run the dense sums' copy took 11-25 ms of each growth).

#include <swslam/map/scan_contribution.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace swslam::map
{
/** Changes to a SummedGrid gathered before they are applied at once (SummedGrid::apply): the
 * sum of the contributions added, in tiles aligned with the grid's, and the boxes of those
 * added with sign +1 in order, so that the grid grows as it would for each in turn. Its memory
 * is bounded by the area the contributions cover, not by their number. */
class SumsChange
{
 public:
  /** Adds `sign` (+1 or -1) times `c`. */
  void add(const ScanContribution& c, int sign);
  bool empty() const { return tiles_.empty(); }
  size_t bytes() const;

 private:
  friend class SummedGrid;
  std::map<std::pair<int, int>, std::unique_ptr<int32_t[]>> tiles_;  ///< (tile y, tile x) -> sums
  std::vector<CellBox> grown_;  ///< boxes added with sign +1, in order
};

class SummedGrid
{
 public:
  /** Cells per side of a tile of sums. */
  static constexpr int kTileSize = 64;
  /** Largest half size and grow margin, in cells (the first map then has at most 2^28 cells). */
  static constexpr int kMaxCellsPerLength = 1 << 13;

  /** Empty map covering [-half_size, half_size]^2; grows by `grow_margin` [m] beyond any
   * contribution that leaves it. Throws std::invalid_argument unless resolution and half size
   * are > 0, the margin >= 0, and both lengths at most kMaxCellsPerLength cells. */
  SummedGrid(double resolution, double half_size, double grow_margin);

  /** Adds `sign` (+1 or -1) times `c` to the sums and refreshes the mirrored cells. */
  void add(const ScanContribution& c, int sign);
  /** Adds `change`: the same sums, cells and bounds as adding its contributions one by one. */
  void apply(const SumsChange& change);

  const mrpt::maps::COccupancyGridMap2D& grid() const { return grid_; }
  const CellBox& box() const { return box_; }
  /** Sum of the deltas at global cell (x, y); 0 outside the grid. */
  int32_t sum(int x, int y) const;
  /** Tiles of sums allocated so far. */
  size_t tileCount() const { return tile_count_; }
  size_t bytes() const;

 private:
  using Tile = std::unique_ptr<int32_t[]>;
  /** The tile holding global cell (x, y) (inside box_), allocated (zeroed) if new. */
  int32_t* tileAt(int x, int y);
  const int32_t* findTile(int x, int y) const;
  size_t tileIndex(int x, int y) const;
  void growToContain(const CellBox& b);
  /** Writes clamp(sum) into the MRPT grid for the cells of tile `t` (tile coordinates) that
   * lie in box_. */
  void mirrorTile(int tx, int ty);

  double resolution_;
  int margin_cells_;
  CellBox box_;         ///< global cells covered by grid_
  CellBox tile_box_;    ///< tiles (global cell / kTileSize) covering box_
  std::vector<Tile> tiles_;  ///< row-major over tile_box_; null: all sums zero
  size_t tile_count_ = 0;
  mrpt::maps::COccupancyGridMap2D grid_;  ///< clamp(sums), over box_
};

}  // namespace swslam::map
