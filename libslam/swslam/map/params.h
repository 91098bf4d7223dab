#pragma once
// Parameters of the occupancy grid map (paper sec. IV), section [map].

#include <swslam/geometry/pose_threshold.h>

#include <swslam/common/param_table.h>
#include <mrpt/core/bits_math.h>

#include <string>

namespace swslam::map
{
/** Parameters of MapBuilder and of the map writers, section [map]: declared in table()
 * (params.cpp). */
struct MapParams
{
  double resolution = 0.2;         ///< [m] cell size
  double initial_half_size = 20;   ///< [m] the grid starts as [-s, s]^2 around the origin
  double grow_margin = 20;         ///< [m] room added beyond a scan that leaves the grid
  double prob_occupied = 0.65;     ///< eq. (16) prop_occupied, for the cell at a ray's end
  double prob_free = 0.35;         ///< eq. (16) prop_free, for the cells a ray crosses
  double max_insertion_range = 80; ///< [m] rays are cut here (no hit inserted beyond)
  double horizontal_tolerance = mrpt::DEG2RAD(0.05);  ///< [rad] a scan tilted more is an error
  double reinsert_translation = 0.1;  ///< [m] a node that moved more is re-inserted...
  double reinsert_rotation = mrpt::DEG2RAD(0.5);  ///< [rad] ...or turned more
  double occupied_thresh = 0.65;   ///< exports: occupancy above this is an obstacle
  double free_thresh = 0.196;      ///< exports: occupancy below this is free

  static const common::ParamTable<MapParams>& table();

  /** How far a node must move to be re-inserted (sec. IV.B). */
  geometry::MoveThreshold reinsertThreshold() const { return {reinsert_translation, reinsert_rotation}; }
};

}  // namespace swslam::map
