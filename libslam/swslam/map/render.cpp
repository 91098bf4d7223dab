#include <swslam/map/render.h>

#include <swslam/common/image_file.h>

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/opengl/CTexturedPlane.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>

namespace swslam::map
{
namespace
{
using Segment = std::pair<mrpt::math::TPoint2D, mrpt::math::TPoint2D>;

/** Segments drawn as flat ribbons `width` [m] wide at height z: GL lines are one pixel at
 * most in a core-profile context, and too faint to see. `dash` > 0 [m] draws dashes that long
 * with gaps of 0.6 dash. */
mrpt::opengl::CSetOfTriangles::Ptr ribbons(const std::vector<Segment>& segments, double width, double z,
                                           const mrpt::img::TColor& color, double dash = 0)
{
  auto obj = mrpt::opengl::CSetOfTriangles::Create();
  auto add = [&](const mrpt::math::TPoint2D& p0, const mrpt::math::TPoint2D& p1) {
    const double len = (p1 - p0).norm();
    if (len <= 0) return;
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
  };
  for (const auto& [p0, p1] : segments)
  {
    const double len = (p1 - p0).norm();
    if (dash <= 0 || len <= dash)
    {
      add(p0, p1);
      continue;
    }
    const auto dir = (p1 - p0) * (1.0 / len);
    for (double s = 0; s < len; s += 1.6 * dash) add(p0 + dir * s, p0 + dir * std::min(len, s + dash));
  }
  return obj;
}

/** How each kind of drawn line looks, bottom to top: along a trajectory the edges are nearly
 * collinear, so each layer is narrower than the one below and shows as a stripe of its own
 * (light-orange trajectory, violet where the prediction placed the scans, teal dense-neighbour
 * edges, dark keyframe squares, blue consecutive edges); loops and switched-off edges on top. */
struct Layer
{
  const char* label;
  mrpt::img::TColor color;
  double width_px;
  LegendEntry::Symbol symbol;
};
using S = LegendEntry::Symbol;
constexpr size_t kTrajectoryLayer = 0, kByPredictionLayer = 1, kNeighbourLayer = 2, kKeyframeLayer = 3,
                 kConsecutiveLayer = 4, kPriorLayer = 5, kLoopLayer = 6, kSwitchedOffLayer = 7;
const std::array<Layer, 8> kLayers = {{{"trajectory", mrpt::img::TColor(255, 185, 90), 8, S::Line},
                                       {"placed by the prediction", colors::kByPrediction, 8, S::Line},
                                       {"dense neighbour edge", colors::kNeighbour, 5, S::Line},
                                       {"keyframe", colors::kKeyframe, 3, S::Dot},
                                       {"consecutive edge", colors::kConsecutive, 1.5, S::Line},
                                       {"prior edge", colors::kPrior, 2, S::Line},
                                       {"loop edge (nodes ringed)", colors::kLoop, 3, S::Line},
                                       {"switched-off edge", colors::kSwitchedOff, 2.5, S::Dashed}}};

size_t layerOf(const OverlayEdge& e)
{
  if (e.switched_off) return kSwitchedOffLayer;
  switch (e.look)
  {
    case EdgeLook::Consecutive: return kConsecutiveLayer;
    case EdgeLook::DenseNeighbour: return kNeighbourLayer;
    case EdgeLook::Prior: return kPriorLayer;
    case EdgeLook::Loop: return kLoopLayer;
  }
  return kConsecutiveLayer;
}

/** The GL picture of the plot area. */
mrpt::img::CImage renderPlot(const mrpt::maps::COccupancyGridMap2D& grid, const PictureView& view,
                             const std::array<std::vector<Segment>, kLayers.size()>& lines)
{
  mrpt::opengl::COpenGLScene scene;
  scene.getViewport()->setCustomBackgroundColor(mrpt::img::TColorf(0.5f, 0.5f, 0.5f));
  // The grid as an opaque texture (MRPT's own visualization makes unknown cells translucent,
  // and translucent planes are drawn over the lines).
  mrpt::img::CImage texture;
  grid.getAsImage(texture, /*verticalFlip=*/true, /*forceRGB=*/true);
  auto map_obj = mrpt::opengl::CTexturedPlane::Create(grid.getXMin(), grid.getXMax(), grid.getYMin(), grid.getYMax());
  map_obj->assignImage(std::move(texture));
  scene.insert(map_obj);

  const double w = view.width * view.metres_per_pixel, h = view.height * view.metres_per_pixel;
  // MRPT's orthographic view spans zoom * aspect / 2 horizontally and zoom / 2 vertically.
  const double zoom = 2 * h;
  // The layers well above the map (between it and the eye), each above the previous one: the
  // orthographic depth range is wide, and ribbons close to the map plane lose the depth test.
  for (size_t i = 0; i < kLayers.size(); i++)
    scene.insert(ribbons(lines[i], kLayers[i].width_px * view.metres_per_pixel, (0.1 + 0.05 * i) * zoom,
                         kLayers[i].color, kLayers[i].symbol == S::Dashed ? 9 * view.metres_per_pixel : 0));

  mrpt::opengl::CCamera cam;
  cam.setOrthogonal(true);
  cam.setPointingAt(static_cast<float>(view.x0 + 0.5 * w), static_cast<float>(view.y1 - 0.5 * h), 0);
  cam.setAzimuthDegrees(-90);
  cam.setElevationDegrees(90);
  cam.setZoomDistance(static_cast<float>(zoom));
  mrpt::img::CImage img;
  try
  {
    mrpt::opengl::CFBORender renderer(view.width, view.height);
    renderer.setCamera(scene, cam);
    renderer.render_RGB(scene, img);
  }
  catch (const std::exception& ex)
  {
    throw std::runtime_error(
        std::string("render: no off-screen OpenGL context (EGL; Debian packages libegl1, "
                    "libegl-mesa0, libgl1-mesa-dri): ") +
        ex.what());
  }
  return img;
}
}  // namespace

mrpt::img::CImage renderMapImage(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay, unsigned width,
                                 unsigned height, RenderLayout* layout)
{
  checkOverlay(overlay);
  if (width < 200 || (height != 0 && height < 200) || width > 8192 || height > 8192)
    throw std::invalid_argument("render: image size must be within [200, 8192] px");

  // The plot area inside the margins, framing the observed area with a 5% border.
  const Extent e = framedExtent(grid, overlay);
  PictureView view;
  view.width = static_cast<int>(width) - kMarginLeft - kMarginRight;
  if (height == 0)  // the plot as tall as the observed area needs, within [width / 2, width]
    view.height = std::clamp(static_cast<int>(std::ceil(view.width * (e.y1 - e.y0) / std::max(e.x1 - e.x0, 1e-9))),
                             view.width / 2, view.width);
  else
    view.height = static_cast<int>(height) - kMarginTop - kMarginBottom;
  const double aspect = double(view.width) / view.height;
  const double span = std::max({e.x1 - e.x0, (e.y1 - e.y0) * aspect, 10.0 * grid.getResolution()}) * 1.05;
  view.metres_per_pixel = span / view.width;
  view.x0 = 0.5 * (e.x0 + e.x1) - 0.5 * span;
  view.y1 = 0.5 * (e.y0 + e.y1) + 0.5 * view.height * view.metres_per_pixel;

  std::array<std::vector<Segment>, kLayers.size()> lines;
  for (size_t i = 1; i < overlay.trajectory.size(); i++)
    lines[overlay.segmentByPrediction(i) ? kByPredictionLayer : kTrajectoryLayer].emplace_back(
        overlay.trajectory[i - 1].translation(), overlay.trajectory[i].translation());
  for (const OverlayEdge& edge : overlay.edges)
    lines[layerOf(edge)].emplace_back(overlay.nodes[edge.from].translation(), overlay.nodes[edge.to].translation());
  // Keyframes: squares of 3 x 3 px (a segment as long as its ribbon is wide).
  const double half = 0.5 * kLayers[kKeyframeLayer].width_px * view.metres_per_pixel;
  for (const auto& p : overlay.nodes)
    lines[kKeyframeLayer].emplace_back(mrpt::math::TPoint2D(p.x() - half, p.y()), mrpt::math::TPoint2D(p.x() + half, p.y()));

  char title[160];
  std::snprintf(title, sizeof(title), "Map (%.3g m cells), trajectory and pose graph: %zu keyframes, %zu edges",
                grid.getResolution(), overlay.nodes.size(), overlay.edges.size());
  mrpt::img::CImage img = framedCanvas(view, title);
  img.drawImage(view.left, view.top, renderPlot(grid, view, lines));
  // The nodes of loop edges ringed (a loop between nodes a few metres apart is a few pixels
  // long, and often lies along the trajectory), under the start and end marks.
  for (const OverlayEdge& edge : overlay.edges)
    if (layerOf(edge) == kLoopLayer)
      for (const size_t n : {edge.from, edge.to})
      {
        const auto q = view.toImage(overlay.nodes[n].x(), overlay.nodes[n].y());
        img.drawCircle(static_cast<int>(std::floor(q.x)), static_cast<int>(std::floor(q.y)), 13, colors::kLoop, 1);
      }
  drawStartAndEnd(img, view, overlay.trajectory);

  std::vector<LegendEntry> legend = mapLegend();
  legend.erase(legend.begin() + 3, legend.end());  // free, occupied, unknown
  for (size_t i = 0; i < kLayers.size(); i++)
  {
    if (lines[i].empty()) continue;
    const Layer& l = kLayers[i];
    std::string label = l.label;
    if (i == kByPredictionLayer)
      label += " (" + std::to_string(overlay.countByPrediction()) + " scans)";
    else if (i != kTrajectoryLayer)
      label += " (" + std::to_string(lines[i].size()) + ")";
    legend.push_back({label, l.color, l.symbol, std::max(2, static_cast<int>(l.width_px))});
  }
  if (!overlay.trajectory.empty())
  {
    legend.push_back({"start", colors::kStart, S::Start, 0});
    legend.push_back({"end", colors::kEnd, S::End, 0});
  }
  RenderLayout l;
  l.view = view;
  l.scale_bar = drawLegendAndScaleBar(img, view, legend, &l.legend);
  if (layout) *layout = l;
  return img;
}

void renderMap(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay, const std::string& path,
               unsigned width, unsigned height)
{
  const mrpt::img::CImage img = renderMapImage(grid, overlay, width, height);
  common::writeImageAtomically(path, img);
}

}  // namespace swslam::map
