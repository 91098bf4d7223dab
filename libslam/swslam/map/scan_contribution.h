#pragma once
// The log-odds change one scan makes to the grid (paper eq. 15-16), in global cell
// coordinates: what a node adds when it is inserted and subtracts when it is removed.

#include <swslam/map/params.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace swslam::map
{
/** Half-open box of global cells: cell (i, j) covers [i, i+1) x [j, j+1) * resolution. */
struct CellBox
{
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool contains(const CellBox& b) const
  {
    return b.empty() || (b.x0 >= x0 && b.y0 >= y0 && b.x1 <= x1 && b.y1 <= y1);
  }
};

/** Sparse log-odds deltas in MRPT's integer cell units (positive = free), stored as
 * one run per row, from the row's first to its last touched cell. */
struct ScanContribution
{
  using Delta = mrpt::maps::COccupancyGridMap2D::cellType;
  struct Run
  {
    int y = 0, x0 = 0;     ///< global cell of the run's first value
    uint32_t offset = 0;   ///< index of that value in `deltas`
    uint32_t length = 0;
  };
  std::vector<Run> runs;
  std::vector<Delta> deltas;
  CellBox box;  ///< bounding box of all runs

  size_t cells() const { return deltas.size(); }
  size_t bytes() const { return runs.size() * sizeof(Run) + deltas.size() * sizeof(Delta); }
};

/** Farthest global cell index a map may reach (either axis, either sign): MRPT keeps a grid's
 * bounds in float (24-bit mantissa), so cell edges stay exact to a quarter cell up to here. A
 * pose beyond it (at the default 0.2 m cells: 839 km from the start) is a corrupt input. */
constexpr int kMaxMapCellIndex = 1 << 22;
/** Most cells a map may hold (2 bytes each in the MRPT grid; 1 GiB cells = 2 GiB): above it,
 * a map growth is refused (a pose far from the rest of the map is a corrupt input). */
constexpr double kMaxMapCells = 1 << 30;

/** Global cell index of coordinate `v` [m]. */
inline int cellOf(double v, double resolution)
{
  return static_cast<int>(std::floor(v / resolution));
}

/** MRPT's insertion options that implement eq. (15)-(16) with the map's parameters. */
mrpt::maps::COccupancyGridMap2D::TInsertionOptions insertionOptions(const MapParams& p);

/** Returns the copy of `obs` that computeContribution() inserts: every ray flagged valid but
 * not a positive finite range below the max range is marked invalid, and the geometry is
 * restated so that MRPT's grid insertion (which steps rays by aperture/N) traces each ray at
 * its true angle (aperture/(N-1) apart, as everywhere else in MRPT). Throws std::invalid_argument naming the problem when the scan's geometry
 * cannot be inserted (fewer than 2 rays, bad aperture, tilted beyond `horizontal_tolerance`). */
mrpt::obs::CObservation2DRangeScan sanitizedScan(const mrpt::obs::CObservation2DRangeScan& obs,
                                                 const MapParams& params);

/** The scratch grid computeContribution() inserts into, kept from call to call so that a
 * map thread does not allocate (and page in) a fresh grid for every scan. One per thread. */
struct ContributionScratch
{
  mrpt::maps::COccupancyGridMap2D grid;
};

/** Eq. (15)-(16) for one scan: inserts `obs` (already sanitized) seen from `vehicle_pose`
 * into an empty scratch grid with MRPT's own insertObservation (log-odds along Bresenham
 * rays, insertionOptions()) and keeps the non-zero cells. Deterministic: the
 * same scan and pose always give the same deltas, whatever the map already holds and
 * whatever `scratch` held before. */
ScanContribution computeContribution(const mrpt::obs::CObservation2DRangeScan& obs,
                                     const mrpt::poses::CPose2D& vehicle_pose,
                                     const MapParams& params, ContributionScratch& scratch);

/** The same with a scratch grid of its own. */
ScanContribution computeContribution(const mrpt::obs::CObservation2DRangeScan& obs,
                                     const mrpt::poses::CPose2D& vehicle_pose,
                                     const MapParams& params);

}  // namespace swslam::map
