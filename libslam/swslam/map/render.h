#pragma once
// Off-screen picture of the map with the trajectory and the graph's edges, rendered with
// MRPT OpenGL (mrpt::opengl::CFBORender over EGL: no window, no display needed).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <utility>
#include <vector>

namespace swslam::map
{
struct RenderInput
{
  std::vector<mrpt::poses::CPose2D> trajectory;   ///< drawn as a polyline (red)
  std::vector<mrpt::poses::CPose2D> nodes;        ///< graph node poses
  std::vector<std::pair<size_t, size_t>> edges;   ///< indices into `nodes` (blue lines)
  unsigned width = 1200, height = 1200;           ///< image size [px]
};

/** Renders `grid` seen from above (orthographic, north up, framing the observed area and
 * the trajectory) and writes a PNG to `path` atomically. Throws std::invalid_argument for an
 * edge index out of range and std::runtime_error naming the problem when no off-screen
 * OpenGL context can be created (e.g. no EGL driver) or the file cannot be written. */
void renderMap(const mrpt::maps::COccupancyGridMap2D& grid, const RenderInput& input,
               const std::string& path);

}  // namespace swslam::map
