#include <swslam/localize/map_score_grid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swslam::localize
{
namespace
{
/** MRPT's getCell() is p(free). */
double occupancy(const mrpt::maps::COccupancyGridMap2D& grid, unsigned x, unsigned y) { return 1.0 - grid.getCell(x, y); }
}  // namespace

std::vector<Eigen::Vector2d> occupiedCells(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh)
{
  std::vector<Eigen::Vector2d> out;
  for (unsigned y = 0; y < grid.getSizeY(); ++y)
    for (unsigned x = 0; x < grid.getSizeX(); ++x)
      if (occupancy(grid, x, y) >= occupied_thresh) out.emplace_back(grid.idx2x(x), grid.idx2y(y));
  return out;
}

correlative::ScoreGrid occupancyScoreGrid(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh,
                                          double free_thresh, double sigma, int free_value, int pad_cells,
                                          size_t max_cells)
{
  // The score grid's cells are the map's, padded on the low sides: a point on a map cell
  // scores that cell's value.
  correlative::ScoreGrid out;
  out.resolution = grid.getResolution();
  out.pad_cells = pad_cells;
  const int w = static_cast<int>(grid.getSizeX()), h = static_cast<int>(grid.getSizeY());
  const double cells = double(w + pad_cells) * double(h + pad_cells);
  if (cells > double(max_cells))
    throw std::length_error("map of " + std::to_string(w) + " x " + std::to_string(h) +
                            " cells: beyond the whole-map search's budget of " + std::to_string(max_cells) +
                            " cells a level");
  bool any_occupied = false;
  for (unsigned y = 0; y < grid.getSizeY() && !any_occupied; ++y)
    for (unsigned x = 0; x < grid.getSizeX() && !any_occupied; ++x) any_occupied = occupancy(grid, x, y) >= occupied_thresh;
  if (!any_occupied) return out;
  out.origin = Eigen::Vector2d(grid.getXMin(), grid.getYMin()) - Eigen::Vector2d::Constant(pad_cells * out.resolution);
  out.width = w + pad_cells;
  out.height = h + pad_cells;
  out.cells.assign(static_cast<size_t>(out.width) * out.height, 0);
  // Each occupied cell's kernel over the cells within 3 sigma: the max over them is the
  // kernel of the nearest occupied cell.
  const int reach = static_cast<int>(std::ceil(3 * sigma / out.resolution));
  std::vector<int16_t> kernel;
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx)
    {
      const double d2 = (dx * dx + dy * dy) * out.resolution * out.resolution;
      kernel.push_back(static_cast<int16_t>(std::lround(255 * std::exp(-d2 / (2 * sigma * sigma)))));
    }
  for (unsigned y = 0; y < grid.getSizeY(); ++y)
    for (unsigned x = 0; x < grid.getSizeX(); ++x)
    {
      if (!(occupancy(grid, x, y) >= occupied_thresh)) continue;
      const int cx = static_cast<int>(x) + pad_cells, cy = static_cast<int>(y) + pad_cells;
      size_t k = 0;
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx, ++k)
        {
          const int gx = cx + dx, gy = cy + dy;
          if (gx < 0 || gy < 0 || gx >= out.width || gy >= out.height) continue;
          int16_t& v = out.cells[static_cast<size_t>(gy) * out.width + gx];
          v = std::max(v, kernel[k]);
        }
    }
  for (unsigned y = 0; y < grid.getSizeY(); ++y)
    for (unsigned x = 0; x < grid.getSizeX(); ++x)
    {
      if (!(occupancy(grid, x, y) < free_thresh)) continue;
      int16_t& v = out.cells[static_cast<size_t>(y + pad_cells) * out.width + x + pad_cells];
      if (v == 0) v = static_cast<int16_t>(free_value);
    }
  return out;
}

}  // namespace swslam::localize
