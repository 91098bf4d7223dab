#include <swslam/sim/grid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
// Shapes are registered in every cell their box touches, grown by this margin so a hit
// on a cell border is found from either side.
constexpr double kMargin = 1e-6;
}  // namespace

ShapeGrid::ShapeGrid(const World& world, double cell_size) : world_(world), cell_(cell_size)
{
  const Box& b = world.bounds;
  if (!(cell_size > 0)) throw std::invalid_argument("ShapeGrid: cell size must be > 0");
  nx_ = std::max<size_t>(1, static_cast<size_t>(std::ceil((b.max_x - b.min_x) / cell_)));
  ny_ = std::max<size_t>(1, static_cast<size_t>(std::ceil((b.max_y - b.min_y) / cell_)));

  const auto cellRange = [&](const Shape& s, size_t& x0, size_t& y0, size_t& x1, size_t& y1) {
    const Box bb = boundingBox(s);
    const auto clampX = [&](double v) {
      return static_cast<size_t>(std::clamp(std::floor((v - b.min_x) / cell_), 0.0, nx_ - 1.0));
    };
    const auto clampY = [&](double v) {
      return static_cast<size_t>(std::clamp(std::floor((v - b.min_y) / cell_), 0.0, ny_ - 1.0));
    };
    x0 = clampX(bb.min_x - kMargin);
    x1 = clampX(bb.max_x + kMargin);
    y0 = clampY(bb.min_y - kMargin);
    y1 = clampY(bb.max_y + kMargin);
  };

  // Two passes (count, then fill) into one flat array.
  std::vector<uint32_t> count(nx_ * ny_ + 1, 0);
  for (const auto& s : world.shapes)
  {
    size_t x0, y0, x1, y1;
    cellRange(s, x0, y0, x1, y1);
    for (size_t iy = y0; iy <= y1; iy++)
      for (size_t ix = x0; ix <= x1; ix++) count[cellIndex(ix, iy) + 1]++;
  }
  first_.assign(nx_ * ny_ + 1, 0);
  for (size_t c = 0; c < nx_ * ny_; c++) first_[c + 1] = first_[c] + count[c + 1];
  shapes_.resize(first_.back());
  std::vector<uint32_t> fill(first_.begin(), first_.end() - 1);
  for (size_t i = 0; i < world.shapes.size(); i++)
  {
    size_t x0, y0, x1, y1;
    cellRange(world.shapes[i], x0, y0, x1, y1);
    for (size_t iy = y0; iy <= y1; iy++)
      for (size_t ix = x0; ix <= x1; ix++)
        shapes_[fill[cellIndex(ix, iy)]++] = static_cast<uint32_t>(i);
  }
}

double ShapeGrid::cast(const Ray& ray, double max_range) const
{
  const Box& b = world_.bounds;
  const double ox = ray.origin.x() - b.min_x, oy = ray.origin.y() - b.min_y;
  const double dx = ray.dir.x(), dy = ray.dir.y();
  long ix = std::clamp(static_cast<long>(std::floor(ox / cell_)), 0L, static_cast<long>(nx_) - 1);
  long iy = std::clamp(static_cast<long>(std::floor(oy / cell_)), 0L, static_cast<long>(ny_) - 1);
  const long step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  // Ray parameter at the next vertical / horizontal cell border, and between borders.
  double t_max_x = dx != 0 ? ((ix + (dx > 0 ? 1 : 0)) * cell_ - ox) / dx : kNoHit;
  double t_max_y = dy != 0 ? ((iy + (dy > 0 ? 1 : 0)) * cell_ - oy) / dy : kNoHit;
  const double t_delta_x = dx != 0 ? cell_ / std::abs(dx) : kNoHit;
  const double t_delta_y = dy != 0 ? cell_ / std::abs(dy) : kNoHit;

  double best = kNoHit;
  for (;;)
  {
    const size_t c = cellIndex(static_cast<size_t>(ix), static_cast<size_t>(iy));
    for (uint32_t k = first_[c]; k < first_[c + 1]; k++)
    {
      const uint32_t i = shapes_[k];
      const Shape& s = world_.shapes[i];
      const double t = hitDistance(s, ray);
      if (t < best && !passesThrough(s, i, ray)) best = t;
    }
    // Every later cell lies beyond t_exit: a hit before it is the nearest.
    const double t_exit = std::min(t_max_x, t_max_y);
    if (best <= t_exit || t_exit > max_range) break;
    if (t_max_x < t_max_y)
    {
      ix += step_x;
      t_max_x += t_delta_x;
    }
    else
    {
      iy += step_y;
      t_max_y += t_delta_y;
    }
    if (ix < 0 || iy < 0 || ix >= static_cast<long>(nx_) || iy >= static_cast<long>(ny_)) break;
  }
  return best <= max_range ? best : kNoHit;
}

}  // namespace swslam::sim
