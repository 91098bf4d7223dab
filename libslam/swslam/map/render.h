#pragma once
// render.png: an off-screen picture of the map with the trajectory and the graph, rendered with
// MRPT OpenGL (mrpt::opengl::CFBORender over EGL: no window, no display needed), then framed
// like map.png (axes in metres, scale bar, start and end, legend).

#include <swslam/map/overlay.h>
#include <swslam/map/picture_annotations.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace swslam::map
{
/** What renderMap drew, for checking the picture. */
struct RenderLayout
{
  PictureView view;
  ScaleBar scale_bar;
  PixelBox legend;
};

/** Renders `grid` seen from above (orthographic, north up, framing the observed area, the
 * trajectory and the nodes) into a width x height image: the trajectory as a wide light orange
 * band, above it, each narrower, dense-neighbour edges (teal), keyframes (dark squares) and
 * consecutive edges (blue), then prior edges (brown), loop edges (magenta, their nodes ringed)
 * and switched-off edges (dashed red), the start and end marks, axes in metres, a scale bar and
 * a legend naming each kind drawn with its count.
 * `height` 0 makes the plot as tall as the observed area needs (between half the plot's width
 * and its width). Throws std::invalid_argument for an edge index out of range or a size outside
 * [200, 8192],
 * std::runtime_error naming the problem when no off-screen OpenGL context can be created
 * (e.g. no EGL driver). */
mrpt::img::CImage renderMapImage(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay,
                                 unsigned width = 1200, unsigned height = 0, RenderLayout* layout = nullptr);

/** Writes renderMapImage() to `path` atomically (std::runtime_error naming the file if not). */
void renderMap(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay, const std::string& path,
               unsigned width = 1200, unsigned height = 0);

}  // namespace swslam::map
