#pragma once
// Every map output of a run, written into one directory: map.gridmap.gz, map.png (picture of
// the grid with the trajectory), map.yaml + map.pgm, map.bt and render.png (the same with the
// pose graph, MRPT OpenGL).

#include <swslam/map/params.h>
#include <swslam/map/overlay.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>
#include <vector>

namespace swslam::map
{
/** One failed output: which file and why. */
struct OutputProblem
{
  std::string file;
  std::string message;
};

/** Writes each map output into `dir` (which must exist), each atomically. One output that
 * fails (e.g. render.png without an EGL driver) does not stop the others: the failures are
 * returned, empty when everything was written. `overlay` is drawn on map.png (the
 * trajectory) and render.png (trajectory and graph); `render` = false skips render.png. */
std::vector<OutputProblem> writeMapOutputs(const std::string& dir, const mrpt::maps::COccupancyGridMap2D& grid,
                                           const MapParams& params, const Overlay& overlay, bool render = true);

}  // namespace swslam::map
