#include "swslam/map/summed_grid.h"

#include <algorithm>
#include <stdexcept>

namespace swslam
{
namespace
{
using Grid = mrpt::maps::COccupancyGridMap2D;

Grid::cellType clampToCell(int32_t v)
{
  return static_cast<Grid::cellType>(
      std::clamp<int32_t>(v, Grid::OCCGRID_CELLTYPE_MIN, Grid::OCCGRID_CELLTYPE_MAX));
}
}  // namespace

SummedGrid::SummedGrid(double resolution, double half_size, double grow_margin)
    : resolution_(resolution),
      margin_cells_(static_cast<int>(std::ceil(grow_margin / resolution)))
{
  if (!(resolution > 0) || !(half_size > 0))
    throw std::invalid_argument("map: resolution and half size must be > 0");
  const int h = static_cast<int>(std::ceil(half_size / resolution));
  box_ = CellBox{-h, -h, h, h};
  sums_.assign(static_cast<size_t>(box_.width()) * box_.height(), 0);
  grid_.setSize(static_cast<float>(box_.x0 * resolution_), static_cast<float>(box_.x1 * resolution_),
                static_cast<float>(box_.y0 * resolution_), static_cast<float>(box_.y1 * resolution_),
                static_cast<float>(resolution_), 0.5f);
}

int32_t SummedGrid::sum(int x, int y) const
{
  if (x < box_.x0 || x >= box_.x1 || y < box_.y0 || y >= box_.y1) return 0;
  return sums_[static_cast<size_t>(y - box_.y0) * box_.width() + (x - box_.x0)];
}

void SummedGrid::add(const ScanContribution& c, int sign)
{
  if (sign != 1 && sign != -1) throw std::invalid_argument("SummedGrid::add: sign must be +-1");
  if (!box_.contains(c.box)) growToContain(c.box);
  const int w = box_.width();
  for (const auto& run : c.runs)
  {
    int32_t* s = &sums_[static_cast<size_t>(run.y - box_.y0) * w + (run.x0 - box_.x0)];
    const auto* d = &c.deltas[run.offset];
    for (uint32_t k = 0; k < run.length; k++) s[k] += sign * d[k];
    mirrorRow(run.y, run.x0, run.x0 + static_cast<int>(run.length));
  }
}

void SummedGrid::mirrorRow(int y, int x0, int x1)
{
  const int32_t* s = &sums_[static_cast<size_t>(y - box_.y0) * box_.width() + (x0 - box_.x0)];
  Grid::cellType* g = grid_.getRow(y - box_.y0) + (x0 - box_.x0);
  for (int k = 0; k < x1 - x0; k++) g[k] = clampToCell(s[k]);
}

void SummedGrid::growToContain(const CellBox& b)
{
  // Grow only the sides that need it, by the margin beyond the contribution.
  CellBox n = box_;
  if (b.x0 < n.x0) n.x0 = b.x0 - margin_cells_;
  if (b.y0 < n.y0) n.y0 = b.y0 - margin_cells_;
  if (b.x1 > n.x1) n.x1 = b.x1 + margin_cells_;
  if (b.y1 > n.y1) n.y1 = b.y1 + margin_cells_;

  std::vector<int32_t> sums(static_cast<size_t>(n.width()) * n.height(), 0);
  for (int y = box_.y0; y < box_.y1; y++)
    std::copy_n(&sums_[static_cast<size_t>(y - box_.y0) * box_.width()], box_.width(),
                &sums[static_cast<size_t>(y - n.y0) * n.width() + (box_.x0 - n.x0)]);
  sums_.swap(sums);
  box_ = n;
  grid_.setSize(static_cast<float>(n.x0 * resolution_), static_cast<float>(n.x1 * resolution_),
                static_cast<float>(n.y0 * resolution_), static_cast<float>(n.y1 * resolution_),
                static_cast<float>(resolution_), 0.5f);
  if (static_cast<int>(grid_.getSizeX()) != n.width() || static_cast<int>(grid_.getSizeY()) != n.height())
    throw std::logic_error("map: MRPT grid size differs from the summed grid");
  for (int y = n.y0; y < n.y1; y++) mirrorRow(y, n.x0, n.x1);
}

}  // namespace swslam
