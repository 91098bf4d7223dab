#include <swslam/map/render.h>

#include <swslam/common/atomic_file.h>

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/opengl/CTexturedPlane.h>

#include <algorithm>
#include <stdexcept>

namespace swslam::map
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

using Segment = std::pair<mrpt::math::TPoint2D, mrpt::math::TPoint2D>;

/** Segments drawn as flat ribbons `width` [m] wide at height z: GL lines are one pixel at
 * most in a core-profile context, and too faint to see. */
mrpt::opengl::CSetOfTriangles::Ptr ribbons(const std::vector<Segment>& segments, double width,
                                           double z, const mrpt::img::TColor& color)
{
  auto obj = mrpt::opengl::CSetOfTriangles::Create();
  for (const auto& [p0, p1] : segments)
  {
    const double len = (p1 - p0).norm();
    if (len <= 0) continue;
    const double nx = -(p1.y - p0.y) / len * 0.5 * width, ny = (p1.x - p0.x) / len * 0.5 * width;
    auto at = [&](const mrpt::math::TPoint2D& p, double s) {
      return mrpt::math::TPoint3Df(static_cast<float>(p.x + s * nx), static_cast<float>(p.y + s * ny),
                                   static_cast<float>(z));
    };
    // Counter-clockwise seen from above: right side of p0, of p1, left side of p1, of p0.
    const auto a = at(p0, -1), b = at(p1, -1), c = at(p1, +1), d = at(p0, +1);
    for (auto t : {mrpt::opengl::TTriangle(a, b, c), mrpt::opengl::TTriangle(a, c, d)})
    {
      for (auto& v : t.vertices) v.setColor(color);
      obj->insertTriangle(t);
    }
  }
  return obj;
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
  // The grid as an opaque texture (MRPT's own visualization makes unknown cells translucent,
  // and translucent planes are drawn over the lines).
  mrpt::img::CImage texture;
  grid.getAsImage(texture, /*verticalFlip=*/true, /*forceRGB=*/true);
  auto map_obj = mrpt::opengl::CTexturedPlane::Create(grid.getXMin(), grid.getXMax(),
                                                      grid.getYMin(), grid.getYMax());
  map_obj->assignImage(std::move(texture));
  scene.insert(map_obj);

  // Orthographic top view, north up, framing the observed area with a small border.
  const Extent e = observedExtent(grid, input);
  const double aspect = double(input.width) / input.height;
  const double span = std::max({e.x1 - e.x0, (e.y1 - e.y0) * aspect, 10.0 * grid.getResolution()}) * 1.05;
  // Edges 1.5 px and the trajectory 2.5 px wide, well above the map (between it and the
  // eye): the orthographic depth range is wide, and ribbons close to the map plane lose
  // the depth test to it.
  const double pixel = span / input.width;
  // MRPT's orthographic view spans zoom * aspect / 2 horizontally.
  const double zoom = 2 * span / aspect;
  std::vector<Segment> edge_segments, path_segments;
  for (const auto& [a, b] : input.edges)
    edge_segments.emplace_back(input.nodes[a].translation(), input.nodes[b].translation());
  for (size_t i = 1; i < input.trajectory.size(); i++)
    path_segments.emplace_back(input.trajectory[i - 1].translation(), input.trajectory[i].translation());
  scene.insert(ribbons(edge_segments, 1.5 * pixel, 0.15 * zoom, mrpt::img::TColor(40, 90, 230)));
  scene.insert(ribbons(path_segments, 2.5 * pixel, 0.3 * zoom, mrpt::img::TColor(230, 30, 30)));

  mrpt::opengl::CCamera cam;
  cam.setOrthogonal(true);
  cam.setPointingAt(static_cast<float>(0.5 * (e.x0 + e.x1)), static_cast<float>(0.5 * (e.y0 + e.y1)), 0);
  cam.setAzimuthDegrees(-90);
  cam.setElevationDegrees(90);
  cam.setZoomDistance(static_cast<float>(zoom));

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
  common::writeAtomically(path, [&](const std::string& tmp) {
    if (!img.saveToFile(tmp)) throw std::runtime_error("cannot save image '" + tmp + "'");
  });
}

}  // namespace swslam::map
