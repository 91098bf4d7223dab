#pragma once
// OctoMap export of the grid: one occupied voxel per cell whose occupancy is above a threshold
// and one free voxel per cell below another (the space the rays crossed), at the grid's
// resolution, in the z = 0 layer; unobserved cells stay unknown. Loadable by octomap::OcTree.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace swslam::map
{
struct OctomapCounts
{
  size_t occupied = 0, free = 0;
};

/** Writes `path` (binary OctoMap, `.bt`) atomically: cells with occupancy above
 * `occupied_thresh` as occupied voxels, below `free_thresh` as free ones. Throws
 * std::runtime_error naming the file when it cannot. */
OctomapCounts writeOctomap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path,
                           double occupied_thresh, double free_thresh);

/** Number of cells of `grid` whose occupancy p = 1 - getCell() is above `occupied_thresh`. */
size_t countOccupied(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh);

}  // namespace swslam::map
