#include <swslam/map/map_picture.h>

#include <swslam/common/image_file.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace swslam::map
{
namespace
{
constexpr int kTargetPlot = 1000;  ///< [px] the plot's larger side, about (k rounded)
constexpr int kMaxPlot = 1500;     ///< [px] unless one pixel per cell is more
constexpr int kMinPlot = 360;      ///< [px] room for the legend and the scale bar
constexpr int kMaxPixelsPerCell = 16;
}  // namespace

mrpt::img::CImage drawMapPicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay,
                                 MapPictureLayout* layout)
{
  checkOverlay(overlay);
  const double res = grid.getResolution();
  // The framed extent in cells, with a margin of 3% (at least 2 cells) on each side.
  const Extent e = framedExtent(grid, overlay);
  int cx0 = static_cast<int>(std::floor((e.x0 - grid.getXMin()) / res));
  int cx1 = static_cast<int>(std::floor((e.x1 - grid.getXMin()) / res));
  int cy0 = static_cast<int>(std::floor((e.y0 - grid.getYMin()) / res));
  int cy1 = static_cast<int>(std::floor((e.y1 - grid.getYMin()) / res));
  const int margin = std::max(2, static_cast<int>(0.03 * std::max(cx1 - cx0, cy1 - cy0)));
  cx0 -= margin, cx1 += margin, cy0 -= margin, cy1 += margin;
  const int cells = std::max(cx1 - cx0, cy1 - cy0) + 1;
  int k = std::clamp(static_cast<int>(std::lround(double(kTargetPlot) / cells)), 1, kMaxPixelsPerCell);
  if (k > 1 && k * cells > kMaxPlot) k--;
  // Small maps: more cells (unknown beyond the grid) so the legend fits.
  const int min_cells = (kMinPlot + k - 1) / k;
  if (cx1 - cx0 + 1 < min_cells) cx0 -= (min_cells - (cx1 - cx0 + 1)) / 2, cx1 = cx0 + min_cells - 1;
  if (cy1 - cy0 + 1 < min_cells) cy0 -= (min_cells - (cy1 - cy0 + 1)) / 2, cy1 = cy0 + min_cells - 1;

  PictureView view;
  view.metres_per_pixel = res / k;
  view.x0 = grid.getXMin() + cx0 * res;
  view.y1 = grid.getYMin() + (cy1 + 1) * res;
  view.width = (cx1 - cx0 + 1) * k;
  view.height = (cy1 - cy0 + 1) * k;

  char title[160];
  std::snprintf(title, sizeof(title), "Occupancy grid, %.3g m cells; trajectory of %zu scans", res,
                overlay.trajectory.size());
  mrpt::img::CImage img = framedCanvas(view, title);
  const int sx = static_cast<int>(grid.getSizeX()), sy = static_cast<int>(grid.getSizeY());
  for (int cy = cy0; cy <= cy1; cy++)
    for (int cx = cx0; cx <= cx1; cx++)
    {
      const bool inside = cx >= 0 && cy >= 0 && cx < sx && cy < sy;
      const long grey = inside ? std::lround(255.0 * grid.getCell(cx, cy)) : 128;
      const uint8_t g = static_cast<uint8_t>(std::clamp(grey, 0L, 255L));
      const int u = view.left + (cx - cx0) * k, v = view.top + (cy1 - cy) * k;
      for (int dv = 0; dv < k; dv++)
        for (int du = 0; du < k; du++)
        {
          uint8_t* px = img(u + du, v + dv);
          px[0] = px[1] = px[2] = g;
        }
    }
  for (size_t i = 1; i < overlay.trajectory.size(); i++)
  {
    const auto a = view.toImage(overlay.trajectory[i - 1].x(), overlay.trajectory[i - 1].y());
    const auto b = view.toImage(overlay.trajectory[i].x(), overlay.trajectory[i].y());
    img.line(static_cast<int>(std::floor(a.x)), static_cast<int>(std::floor(a.y)), static_cast<int>(std::floor(b.x)),
             static_cast<int>(std::floor(b.y)),
             overlay.segmentByPrediction(i) ? colors::kByPrediction : colors::kTrajectory, 2);
  }
  drawStartAndEnd(img, view, overlay.trajectory);
  MapPictureLayout l;
  l.view = view;
  l.pixels_per_cell = k;
  std::vector<LegendEntry> legend = mapLegend();
  if (const size_t n = overlay.countByPrediction(); n > 0)
  {
    auto at = std::find_if(legend.begin(), legend.end(), [](const LegendEntry& e) { return e.label == "trajectory"; });
    legend.insert(at == legend.end() ? at : at + 1, {"placed by the prediction (" + std::to_string(n) + " scans)",
                                                     colors::kByPrediction, LegendEntry::Symbol::Line, 3});
  }
  l.scale_bar = drawLegendAndScaleBar(img, view, legend, &l.legend);
  if (layout) *layout = l;
  return img;
}

void writeMapPicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay, const std::string& path)
{
  const mrpt::img::CImage img = drawMapPicture(grid, overlay);
  common::writeImageAtomically(path, img);
}

}  // namespace swslam::map
