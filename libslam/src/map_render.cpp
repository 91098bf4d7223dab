#include "swslam/map/map_render.h"

#include "swslam/atomic_file.h"

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <algorithm>
#include <stdexcept>

namespace swslam
{
namespace
{
struct Extent
{
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y)
  {
    x0 = std::min(x0, x), x1 = std::max(x1, x);
    y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  bool valid() const { return x1 >= x0 && y1 >= y0; }
};

/** Observed cells (not at the 0.5 prior) and the trajectory: what the picture frames. */
Extent observedExtent(const mrpt::maps::COccupancyGridMap2D& grid, const RenderInput& in)
{
  Extent e;
  const auto& raw = grid.getRawMap();
  const unsigned w = grid.getSizeX();
  for (size_t i = 0; i < raw.size(); i++)
    if (raw[i] != 0) e.add(grid.idx2x(i % w), grid.idx2y(i / w));
  for (const auto& p : in.trajectory) e.add(p.x(), p.y());
  for (const auto& p : in.nodes) e.add(p.x(), p.y());
  if (!e.valid())
  {
    e.add(grid.getXMin(), grid.getYMin());
    e.add(grid.getXMax(), grid.getYMax());
  }
  return e;
}

mrpt::opengl::CSetOfLines::Ptr lines(float width, uint8_t r, uint8_t g, uint8_t b)
{
  auto l = mrpt::opengl::CSetOfLines::Create();
  l->setLineWidth(width);
  l->setColor_u8(r, g, b);
  return l;
}
}  // namespace

void renderMap(const mrpt::maps::COccupancyGridMap2D& grid, const RenderInput& input,
               const std::string& path)
{
  for (const auto& [a, b] : input.edges)
    if (a >= input.nodes.size() || b >= input.nodes.size())
      throw std::invalid_argument("render: edge (" + std::to_string(a) + ", " + std::to_string(b) +
                                  ") refers to a node beyond the " +
                                  std::to_string(input.nodes.size()) + " given");
  if (input.width < 16 || input.height < 16 || input.width > 8192 || input.height > 8192)
    throw std::invalid_argument("render: image size must be within [16, 8192] px");

  mrpt::opengl::COpenGLScene scene;
  scene.getViewport()->setCustomBackgroundColor(mrpt::img::TColorf(0.55f, 0.55f, 0.55f));
  auto map_obj = mrpt::opengl::CSetOfObjects::Create();
  grid.getVisualizationInto(*map_obj);
  scene.insert(map_obj);

  const double res = grid.getResolution();
  auto edges = lines(1.5f, 40, 90, 230);
  for (const auto& [a, b] : input.edges)
    edges->appendLine(input.nodes[a].x(), input.nodes[a].y(), 0.02, input.nodes[b].x(),
                      input.nodes[b].y(), 0.02);
  scene.insert(edges);
  auto path_obj = lines(2.5f, 230, 30, 30);
  for (size_t i = 1; i < input.trajectory.size(); i++)
    path_obj->appendLine(input.trajectory[i - 1].x(), input.trajectory[i - 1].y(), 0.04,
                         input.trajectory[i].x(), input.trajectory[i].y(), 0.04);
  scene.insert(path_obj);

  // Orthographic top view, north up, framing the observed area with a small border.
  const Extent e = observedExtent(grid, input);
  const double aspect = double(input.width) / input.height;
  const double span = std::max({e.x1 - e.x0, (e.y1 - e.y0) * aspect, 10 * res}) * 1.05;
  mrpt::opengl::CCamera cam;
  cam.setOrthogonal(true);
  cam.setPointingAt(static_cast<float>(0.5 * (e.x0 + e.x1)), static_cast<float>(0.5 * (e.y0 + e.y1)), 0);
  cam.setAzimuthDegrees(-90);
  cam.setElevationDegrees(90);
  cam.setZoomDistance(static_cast<float>(span / aspect));

  mrpt::img::CImage img;
  try
  {
    mrpt::opengl::CFBORender renderer(input.width, input.height);
    renderer.setCamera(scene, cam);
    renderer.render_RGB(scene, img);
  }
  catch (const std::exception& ex)
  {
    throw std::runtime_error(
        std::string("render: no off-screen OpenGL context (EGL; Debian packages libegl1, "
                    "libegl-mesa0, libgl1-mesa-dri): ") + ex.what());
  }
  writeAtomically(path, [&](const std::string& tmp) {
    if (!img.saveToFile(tmp)) throw std::runtime_error("cannot save image '" + tmp + "'");
  });
}

}  // namespace swslam
