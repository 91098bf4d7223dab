#include <swslam/map/change_picture.h>

#include <swslam/common/image_file.h>
#include <swslam/map/map_picture.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace swslam::map
{
namespace
{
mrpt::img::TColor colourOf(ChangeKind k)
{
  return k == ChangeKind::Appeared ? mrpt::img::TColor(0, 160, 0) : mrpt::img::TColor(220, 0, 0);
}
}  // namespace

mrpt::img::CImage drawChangePicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay,
                                    const ChangeReport& report)
{
  MapPictureLayout layout;
  mrpt::img::CImage img = drawMapPicture(grid, overlay, &layout);
  const double res = report.resolution;
  for (const ChangeRegion& r : report.regions)
  {
    const auto colour = colourOf(r.kind);
    for (const auto& [gx, gy] : r.cells)
    {
      const auto top_left = layout.view.toImage(gx * res, (gy + 1) * res);
      const auto bottom_right = layout.view.toImage((gx + 1) * res, gy * res);
      img.filledRectangle(static_cast<int>(std::floor(top_left.x)), static_cast<int>(std::floor(top_left.y)),
                          static_cast<int>(std::ceil(bottom_right.x)) - 1, static_cast<int>(std::ceil(bottom_right.y)) - 1,
                          colour);
    }
    const auto c = layout.view.toImage(r.x, r.y);
    const int radius = std::max(8, static_cast<int>(0.5 * r.extent() / layout.view.metres_per_pixel) + 6);
    img.drawCircle(static_cast<int>(c.x), static_cast<int>(c.y), radius, colour, 2);
  }
  return img;
}

void writeChangePicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay, const ChangeReport& report,
                        const std::string& path)
{
  common::writeImageAtomically(path, drawChangePicture(grid, overlay, report));
}

std::string formatChangeReport(const ChangeReport& report)
{
  std::string out = "# What changed since the session's survey\n\n";
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "Compared %zu cells both surveys observed. Appeared (free before, occupied now): %zu regions, %.2f m^2. "
                "Disappeared (occupied before, free now): %zu regions, %.2f m^2.\n\n",
                report.compared_cells, report.count(ChangeKind::Appeared), report.area(ChangeKind::Appeared),
                report.count(ChangeKind::Disappeared), report.area(ChangeKind::Disappeared));
  out += buf;
  if (report.regions.empty()) return out;
  out += "| kind | x [m] | y [m] | extent [m] | area [m^2] | cells |\n|---|---|---|---|---|---|\n";
  for (const ChangeRegion& r : report.regions)
  {
    std::snprintf(buf, sizeof(buf), "| %s | %.2f | %.2f | %.2f | %.2f | %zu |\n", toString(r.kind), r.x, r.y,
                  r.extent(), r.area, r.cells.size());
    out += buf;
  }
  return out;
}

}  // namespace swslam::map
