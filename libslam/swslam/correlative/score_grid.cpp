#include <swslam/correlative/score_grid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <stdexcept>
#include <string>

namespace swslam::correlative
{
namespace
{
/** "W x H cells (A x B m at R m)" for a grid's size in errors. */
std::string describeSize(double width, double height, double resolution)
{
  char buf[160];
  std::snprintf(buf, sizeof(buf), "%.4g x %.4g cells (%.4g x %.4g m at %g m)", width, height, width * resolution,
                height * resolution, resolution);
  return buf;
}
}  // namespace

ScoreGrid buildScoreGrid(const std::vector<Eigen::Vector2d>& points, double resolution, double sigma,
                         int pad_cells, const std::vector<Eigen::Vector2d>& cover, size_t max_cells)
{
  if (!(resolution > 0) || !(sigma > 0) || pad_cells < 0)
    throw std::invalid_argument("buildScoreGrid: resolution and sigma must be > 0, pad_cells >= 0");
  ScoreGrid g;
  g.resolution = resolution;
  g.pad_cells = pad_cells;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  for (const auto& p : points)
    if (p.allFinite())
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  if (!(lo.x() <= hi.x())) return g;  // no finite point
  // Every size in double first, checked against the budget before it becomes an int: points
  // (or rays' origins) far apart, or a kernel wide for the cells, ask for more than any grid.
  const double reach = 3 * sigma;
  const double reach_cells_d = std::ceil(reach / resolution);
  // The cells are laid from the points alone; whole cells are added for `cover`.
  g.origin = lo - Eigen::Vector2d::Constant((reach_cells_d + pad_cells) * resolution);
  auto cell = [&](const Eigen::Vector2d& p) -> Eigen::Vector2d {
    return ((p - g.origin) / resolution).array().floor().matrix();
  };
  Eigen::Vector2d top = cell(hi) + Eigen::Vector2d::Constant(reach_cells_d), below = Eigen::Vector2d::Zero();
  for (const auto& p : cover)
  {
    if (!p.allFinite()) continue;
    const Eigen::Vector2d c = cell(p);
    below = below.cwiseMax(-c);
    top = top.cwiseMax(c);
  }
  const Eigen::Vector2d size = top + below + Eigen::Vector2d::Ones();
  if (!(size.x() * size.y() <= static_cast<double>(max_cells)))
    throw std::length_error("score grid of " + describeSize(size.x(), size.y(), resolution) +
                            ": beyond the search's budget of " + std::to_string(max_cells) +
                            " cells (its points, or the rays' origins, spread too far)");
  const int reach_cells = static_cast<int>(reach_cells_d);  // within the grid's size: an int
  g.origin -= below * resolution;
  g.width = static_cast<int>(size.x());
  g.height = static_cast<int>(size.y());
  g.cells.assign(static_cast<size_t>(g.width) * g.height, 0);
  // The max of the points' kernels is the kernel of the nearest point. The kernel is the
  // product of its x and y factors, each computed once per column and row of a point's square,
  // which is clipped to the grid (far from the origin, rounding may shift a point's cell).
  const double inv2s2 = 1 / (2 * sigma * sigma);
  const int side = 2 * reach_cells + 1;
  std::vector<double> dx2(side), dy2(side), ex(side), ey(side);
  for (const auto& p : points)
  {
    if (!p.allFinite()) continue;
    const Eigen::Vector2i c = g.cellOf(p);
    for (int k = 0; k < side; k++)
    {
      const double dx = g.origin.x() + (c.x() - reach_cells + k + 0.5) * resolution - p.x();
      const double dy = g.origin.y() + (c.y() - reach_cells + k + 0.5) * resolution - p.y();
      dx2[k] = dx * dx;
      dy2[k] = dy * dy;
      ex[k] = std::exp(-dx2[k] * inv2s2);
      ey[k] = std::exp(-dy2[k] * inv2s2);
    }
    const int x0 = c.x() - reach_cells, y0 = c.y() - reach_cells;
    const int kx_begin = std::max(0, -x0), kx_end = std::min(side, g.width - x0);
    const int ky_begin = std::max(0, -y0), ky_end = std::min(side, g.height - y0);
    for (int ky = ky_begin; ky < ky_end; ky++)
    {
      int16_t* row = g.cells.data() + static_cast<size_t>(y0 + ky) * g.width + x0;
      for (int kx = kx_begin; kx < kx_end; kx++)
      {
        if (dx2[kx] + dy2[ky] > reach * reach) continue;
        const auto v = static_cast<int16_t>(255 * ex[kx] * ey[ky] + 0.5);
        row[kx] = std::max(row[kx], v);
      }
    }
  }
  return g;
}

void markFreeSpace(ScoreGrid& g, const std::vector<Ray>& rays, int free_value)
{
  if (free_value > 0) throw std::invalid_argument("markFreeSpace: free_value must be <= 0");
  const double step = g.resolution / 2;
  // In cell units: the point origin + s u lies in cell floor(o + s v), with o the origin's and
  // v the direction's coordinates divided by the resolution (no division per point).
  const double inv = 1 / g.resolution;
  for (const Ray& r : rays)
  {
    const Eigen::Vector2d d = r.hit - r.origin;
    const double length = d.norm();
    if (!(length > 0) || !std::isfinite(length) || !r.origin.allFinite()) continue;
    const double ox = (r.origin.x() - g.origin.x()) * inv, oy = (r.origin.y() - g.origin.y()) * inv;
    const double vx = d.x() / length * inv, vy = d.y() / length * inv;
    // The part of the ray inside the grid, s in [enter, leave) (Liang-Barsky): a ray from far
    // away walks only the grid's cells.
    double enter = 0, leave = length;
    for (const auto& [o, v, n] : {std::tuple{ox, vx, g.width}, std::tuple{oy, vy, g.height}})
    {
      if (v == 0)
      {
        if (!(o >= 0 && o < n)) leave = -1;
        continue;
      }
      const double a = -o / v, b = (n - o) / v;
      enter = std::max(enter, std::min(a, b));
      leave = std::min(leave, std::max(a, b));
    }
    if (!(enter < leave)) continue;
    // A ray starting outside is walked from where it enters; its walk is at most the grid's
    // diagonal (far away, enter and leave keep no precision) and one step past its exit: the
    // cell check below keeps what lies outside.
    const double px = ox + enter * vx, py = oy + enter * vy;
    const double last = std::min(leave - enter, std::hypot(g.width, g.height) * g.resolution) + step;
    for (double s = 0; s < last && enter + s < length; s += step)
    {
      const int x = cellFloor(px + s * vx), y = cellFloor(py + s * vy);
      if (static_cast<unsigned>(x) >= static_cast<unsigned>(g.width) ||
          static_cast<unsigned>(y) >= static_cast<unsigned>(g.height))
        continue;
      int16_t& cell = g.cells[static_cast<size_t>(y) * g.width + x];
      if (cell == 0) cell = static_cast<int16_t>(free_value);
    }
  }
}

ScorePyramid::ScorePyramid(ScoreGrid base, int depth)
{
  if (depth < 0 || depth > 20 || base.pad_cells < (1 << depth) - 1)
    throw std::invalid_argument("ScorePyramid: depth " + std::to_string(depth) +
                                " needs a base grid padded by 2^depth - 1 cells (it has " +
                                std::to_string(base.pad_cells) + ")");
  if (base.cells.size() > kMaxPyramidCells / (static_cast<size_t>(depth) + 1))
    throw std::length_error("score pyramid of " + std::to_string(depth + 1) + " levels of " +
                            describeSize(base.width, base.height, base.resolution) + ": beyond the search's budget of " +
                            std::to_string(kMaxPyramidCells) + " cells");
  levels.push_back(std::move(base));
  // Level h from level h-1: the window of side 2^h is the four windows of side 2^(h-1) at
  // offsets 0 and s = 2^(h-1) on each axis. A partner outside the grid scores 0
  // (ScoreGrid::at), which a free cell is below. Each level is written once, without a copy
  // of the one below or a buffer between them.
  const int w = levels.front().width, ht = levels.front().height;
  levels.reserve(static_cast<size_t>(depth) + 1);
  for (int h = 1; h <= depth; h++)
  {
    const int s = 1 << (h - 1);
    const ScoreGrid& below = levels.back();
    ScoreGrid next;
    next.origin = below.origin;
    next.resolution = below.resolution;
    next.width = w;
    next.height = ht;
    next.pad_cells = below.pad_cells;
    next.cells.resize(below.cells.size());
    const int16_t* prev = below.cells.data();
    const int inner = std::max(0, w - s);
    for (int y = 0; y < ht; y++)
    {
      const int16_t* a = prev + static_cast<size_t>(y) * w;
      const int16_t* b = y + s < ht ? a + static_cast<size_t>(s) * w : nullptr;
      int16_t* out = next.cells.data() + static_cast<size_t>(y) * w;
      if (b)
      {
        for (int x = 0; x < inner; x++) out[x] = std::max(std::max(a[x], a[x + s]), std::max(b[x], b[x + s]));
        for (int x = inner; x < w; x++) out[x] = std::max(std::max(a[x], b[x]), int16_t{0});
      }
      else
      {
        for (int x = 0; x < inner; x++) out[x] = std::max(std::max(a[x], a[x + s]), int16_t{0});
        for (int x = inner; x < w; x++) out[x] = std::max(a[x], int16_t{0});
      }
    }
    levels.push_back(std::move(next));
  }
}

std::vector<Eigen::Vector2d> thinPoints(const std::vector<Eigen::Vector2d>& points,
                                        double min_spacing, double max_range)
{
  std::vector<Eigen::Vector2d> out;
  for (const auto& p : points)
  {
    if (p.norm() > max_range) continue;
    if (!out.empty() && (p - out.back()).norm() < min_spacing) continue;
    out.push_back(p);
  }
  return out;
}

}  // namespace swslam::correlative
