#pragma once
// The saved occupancy grid as a correlative search's score grid (correlative/score_grid.h):
// what a scan is matched against when it may be anywhere on the map.

#include <swslam/correlative/score_grid.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

#include <vector>

namespace swslam::localize
{
/** The centres of the cells whose occupancy is at least `occupied_thresh`. */
std::vector<Eigen::Vector2d> occupiedCells(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh);

/** The score grid of the occupied cells (kernel `sigma`, on the map's own cells, padded by
 * `pad_cells` on its low sides), and `free_value` (in [-255, 0]) on the cells the map holds as
 * free (occupancy below `free_thresh`) that no kernel reaches. An empty grid for a map with no
 * occupied cell. Throws std::length_error, before allocating, for a grid (padding included) of
 * more than `max_cells` cells. */
correlative::ScoreGrid occupancyScoreGrid(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh,
                                          double free_thresh, double sigma, int free_value, int pad_cells,
                                          size_t max_cells = correlative::kMaxPyramidCells);

}  // namespace swslam::localize
