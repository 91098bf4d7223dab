#include <swslam/correlative/score_grid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swslam::correlative
{
ScoreGrid buildScoreGrid(const std::vector<Eigen::Vector2d>& points, double resolution,
                         double sigma, int pad_cells, const std::vector<Eigen::Vector2d>& cover)
{
  if (!(resolution > 0) || !(sigma > 0) || pad_cells < 0)
    throw std::invalid_argument("buildScoreGrid: resolution and sigma must be > 0, pad_cells >= 0");
  ScoreGrid g;
  g.resolution = resolution;
  g.pad_cells = pad_cells;
  if (points.empty()) return g;
  Eigen::Vector2d lo = points.front(), hi = points.front();
  for (const auto& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double reach = 3 * sigma;
  const int reach_cells = static_cast<int>(std::ceil(reach / resolution));
  // The cells are laid from the points alone; whole cells are added for `cover`.
  g.origin = lo - Eigen::Vector2d::Constant((reach_cells + pad_cells) * resolution);
  Eigen::Vector2i top = g.cellOf(hi) + Eigen::Vector2i::Constant(reach_cells);
  Eigen::Vector2i below = Eigen::Vector2i::Zero();
  for (const auto& p : cover)
  {
    if (!p.allFinite()) continue;
    const Eigen::Vector2i c = g.cellOf(p);
    below = below.cwiseMax(-c);
    top = top.cwiseMax(c);
  }
  g.origin -= below.cast<double>() * resolution;
  g.width = top.x() + below.x() + 1;
  g.height = top.y() + below.y() + 1;
  g.cells.assign(static_cast<size_t>(g.width) * g.height, 0);
  // The max of the points' kernels is the kernel of the nearest point. The kernel is the
  // product of its x and y factors, each computed once per column and row of a point's square.
  const double inv2s2 = 1 / (2 * sigma * sigma);
  const int side = 2 * reach_cells + 1;
  std::vector<double> dx2(side), dy2(side), ex(side), ey(side);
  for (const auto& p : points)
  {
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
    for (int ky = 0; ky < side; ky++)
    {
      int16_t* row = g.cells.data() + static_cast<size_t>(c.y() - reach_cells + ky) * g.width + (c.x() - reach_cells);
      for (int kx = 0; kx < side; kx++)
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
  auto floorOf = [](double v) {
    const int i = static_cast<int>(v);
    return i - (v < i);
  };
  for (const Ray& r : rays)
  {
    const Eigen::Vector2d d = r.hit - r.origin;
    const double length = d.norm();
    if (!(length > 0)) continue;
    const double ox = (r.origin.x() - g.origin.x()) * inv, oy = (r.origin.y() - g.origin.y()) * inv;
    const double vx = d.x() / length * inv, vy = d.y() / length * inv;
    for (double s = 0; s < length; s += step)
    {
      const int x = floorOf(ox + s * vx), y = floorOf(oy + s * vy);
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
