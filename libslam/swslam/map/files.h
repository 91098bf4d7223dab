#pragma once
// Grid map files: MRPT's own serialization and the ROS map_server pair (the pictures are in
// map_picture.h and render.h).
// Every writer writes atomically (swslam/atomic_file.h) and throws std::runtime_error
// naming the file when it cannot.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace swslam::map
{
/** `map.gridmap.gz`: the grid serialized by MRPT, gzip-compressed. */
void writeGridmap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path);
/** Reads a file written by writeGridmap(). Throws std::runtime_error naming the file. */
mrpt::maps::COccupancyGridMap2D readGridmap(const std::string& path);

/** The ROS map_server thresholds and pixel convention. */
struct RosMapThresholds
{
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
};

/** `NAME.yaml` + `NAME.pgm` (map_server format, negate 0: pixel = 255 * (1 - p(occupied)),
 * first row = largest y; origin = the lower-left corner of the grid, yaw 0). `yaml_path`
 * must end in ".yaml"; the image goes beside it with the extension ".pgm". */
void writeRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& yaml_path,
                 const RosMapThresholds& thresholds);

}  // namespace swslam::map
