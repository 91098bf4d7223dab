#pragma once
// OctoMap export of the grid's occupied cells: one voxel per cell whose occupancy is above
// a threshold, at the grid's resolution, in the z = 0 layer. Loadable by octomap::OcTree.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace swslam::map
{
/** Writes `path` (binary OctoMap, `.bt`) atomically; returns the number of occupied voxels.
 * Throws std::runtime_error naming the file when it cannot. */
size_t writeOctomap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path,
                    double occupied_thresh);

/** Number of cells of `grid` whose occupancy p = 1 - getCell() is above `occupied_thresh`. */
size_t countOccupied(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh);

}  // namespace swslam::map
