#pragma once
// Spatial index of a simulated world: a uniform grid of square cells, each listing the
// shapes whose bounding box touches it. A ray walks the cells it crosses in order
// (Amanatides & Woo's DDA) and stops at the first cell that holds its nearest hit,
// so casting costs a few cells instead of every shape.

#include <swslam/sim/world.h>

#include <cstdint>
#include <vector>

namespace swslam::sim
{
class ShapeGrid
{
 public:
  /** Indexes `world` (which must outlive the grid) with square cells of `cell_size` m. */
  ShapeGrid(const World& world, double cell_size);

  /** Same result as castBruteForce(world, ray, max_range). The ray origin must lie
   * inside the world bounds. */
  double cast(const Ray& ray, double max_range) const;

  size_t cellsX() const { return nx_; }
  size_t cellsY() const { return ny_; }

 private:
  const World& world_;
  double cell_;
  size_t nx_, ny_;
  std::vector<uint32_t> first_;   ///< cell c lists shapes_[first_[c] .. first_[c+1])
  std::vector<uint32_t> shapes_;  ///< shape indices, grouped by cell

  size_t cellIndex(size_t ix, size_t iy) const { return iy * nx_ + ix; }
};

}  // namespace swslam::sim
