#include <swslam/map/summed_grid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::map
{
namespace
{
using Grid = mrpt::maps::COccupancyGridMap2D;

Grid::cellType clampToCell(int32_t v)
{
  return static_cast<Grid::cellType>(
      std::clamp<int32_t>(v, Grid::OCCGRID_CELLTYPE_MIN, Grid::OCCGRID_CELLTYPE_MAX));
}

/** The tile of global cell index v (floor division, also for negative cells). */
int tileOf(int v)
{
  return v >= 0 ? v / SummedGrid::kTileSize : -((-v - 1) / SummedGrid::kTileSize) - 1;
}

CellBox tilesCovering(const CellBox& b)
{
  return CellBox{tileOf(b.x0), tileOf(b.y0), tileOf(b.x1 - 1) + 1, tileOf(b.y1 - 1) + 1};
}

constexpr size_t kTileCells = static_cast<size_t>(SummedGrid::kTileSize) * SummedGrid::kTileSize;

/** ceil(length / resolution) as a cell count, checked before the cast (a NaN, an infinity or
 * a count past an int's range would make the cast undefined). */
int cellCount(double length, double resolution, const char* what)
{
  const double n = std::ceil(length / resolution);
  if (!(n >= 0 && n <= SummedGrid::kMaxCellsPerLength))
    throw std::invalid_argument(std::string("map: ") + what + " " + std::to_string(length) + " m is " +
                                std::to_string(n) + " cells at " + std::to_string(resolution) +
                                " m (at most " + std::to_string(SummedGrid::kMaxCellsPerLength) + ")");
  return static_cast<int>(n);
}

void checkSign(int sign)
{
  if (sign != 1 && sign != -1) throw std::invalid_argument("SummedGrid: a contribution's sign must be +-1");
}

/** Calls f(x, y, offset, n) for each piece of `c`'s runs that lies in one tile: cells x .. x+n-1
 * of row y, whose deltas start at c.deltas[offset]. */
template <class F>
void forEachTilePiece(const ScanContribution& c, F&& f)
{
  for (const auto& run : c.runs)
    for (int k = 0; k < static_cast<int>(run.length);)
    {
      const int x = run.x0 + k;
      const int n = std::min(static_cast<int>(run.length) - k, SummedGrid::kTileSize - (x - tileOf(x) * SummedGrid::kTileSize));
      f(x, run.y, run.offset + k, n);
      k += n;
    }
}

/** Index in a tile of global cell (x, y). */
int inTile(int x, int y)
{
  return (y - tileOf(y) * SummedGrid::kTileSize) * SummedGrid::kTileSize + (x - tileOf(x) * SummedGrid::kTileSize);
}
}  // namespace

void SumsChange::add(const ScanContribution& c, int sign)
{
  checkSign(sign);
  if (sign > 0 && !c.runs.empty()) grown_.push_back(c.box);
  forEachTilePiece(c, [&](int x, int y, size_t offset, int n) {
    auto& tile = tiles_[{tileOf(y), tileOf(x)}];
    if (!tile) tile = std::make_unique<int32_t[]>(kTileCells);
    int32_t* s = tile.get() + inTile(x, y);
    for (int i = 0; i < n; i++) s[i] += sign * c.deltas[offset + i];
  });
}

size_t SumsChange::bytes() const
{
  return tiles_.size() * kTileCells * sizeof(int32_t) + grown_.size() * sizeof(CellBox);
}

SummedGrid::SummedGrid(double resolution, double half_size, double grow_margin) : resolution_(resolution)
{
  if (!(resolution > 0) || !(half_size > 0) || !(grow_margin >= 0))
    throw std::invalid_argument("map: resolution and half size must be > 0, grow margin >= 0");
  margin_cells_ = cellCount(grow_margin, resolution, "grow margin");
  const int h = cellCount(half_size, resolution, "half size");
  box_ = CellBox{-h, -h, h, h};
  tile_box_ = tilesCovering(box_);
  tiles_.resize(static_cast<size_t>(tile_box_.width()) * tile_box_.height());
  grid_.setSize(static_cast<float>(box_.x0 * resolution_), static_cast<float>(box_.x1 * resolution_),
                static_cast<float>(box_.y0 * resolution_), static_cast<float>(box_.y1 * resolution_),
                static_cast<float>(resolution_), 0.5f);
}

size_t SummedGrid::tileIndex(int x, int y) const
{
  return static_cast<size_t>(tileOf(y) - tile_box_.y0) * tile_box_.width() +
         static_cast<size_t>(tileOf(x) - tile_box_.x0);
}

int32_t* SummedGrid::tileAt(int x, int y)
{
  Tile& t = tiles_[tileIndex(x, y)];
  if (!t)
  {
    t = std::make_unique<int32_t[]>(kTileCells);  // value-initialized: zero
    tile_count_++;
  }
  return t.get();
}

const int32_t* SummedGrid::findTile(int x, int y) const { return tiles_[tileIndex(x, y)].get(); }

int32_t SummedGrid::sum(int x, int y) const
{
  if (x < box_.x0 || x >= box_.x1 || y < box_.y0 || y >= box_.y1) return 0;
  const int32_t* t = findTile(x, y);
  if (!t) return 0;
  return t[(y - tileOf(y) * kTileSize) * kTileSize + (x - tileOf(x) * kTileSize)];
}

void SummedGrid::add(const ScanContribution& c, int sign)
{
  checkSign(sign);
  if (!box_.contains(c.box)) growToContain(c.box);
  forEachTilePiece(c, [&](int x, int y, size_t offset, int n) {
    int32_t* s = tileAt(x, y) + inTile(x, y);
    Grid::cellType* g = grid_.getRow(y - box_.y0) + (x - box_.x0);
    for (int i = 0; i < n; i++)
    {
      s[i] += sign * c.deltas[offset + i];
      g[i] = clampToCell(s[i]);
    }
  });
}

void SummedGrid::apply(const SumsChange& change)
{
  for (const auto& b : change.grown_)
    if (!box_.contains(b)) growToContain(b);
  for (const auto& [tile, sums] : change.tiles_)
  {
    const auto [ty, tx] = tile;
    int32_t* s = tileAt(tx * kTileSize, ty * kTileSize);
    for (size_t i = 0; i < kTileCells; i++) s[i] += sums[i];
    mirrorTile(tx, ty);
  }
}

void SummedGrid::mirrorTile(int tx, int ty)
{
  const int32_t* t = tiles_[static_cast<size_t>(ty - tile_box_.y0) * tile_box_.width() +
                            (tx - tile_box_.x0)].get();
  if (!t) return;
  const int x0 = std::max(box_.x0, tx * kTileSize), x1 = std::min(box_.x1, (tx + 1) * kTileSize);
  const int y0 = std::max(box_.y0, ty * kTileSize), y1 = std::min(box_.y1, (ty + 1) * kTileSize);
  for (int y = y0; y < y1; y++)
  {
    const int32_t* s = t + (y - ty * kTileSize) * kTileSize + (x0 - tx * kTileSize);
    Grid::cellType* g = grid_.getRow(y - box_.y0) + (x0 - box_.x0);
    for (int k = 0; k < x1 - x0; k++) g[k] = clampToCell(s[k]);
  }
}

void SummedGrid::growToContain(const CellBox& b)
{
  // Grow only the sides that need it, by the margin beyond the contribution.
  CellBox n = box_;
  if (b.x0 < n.x0) n.x0 = b.x0 - margin_cells_;
  if (b.y0 < n.y0) n.y0 = b.y0 - margin_cells_;
  if (b.x1 > n.x1) n.x1 = b.x1 + margin_cells_;
  if (b.y1 > n.y1) n.y1 = b.y1 + margin_cells_;
  if (static_cast<double>(n.width()) * n.height() > kMaxMapCells)
  {
    auto m = [this](int cell) { return std::to_string(cell * resolution_); };
    throw std::runtime_error("map: a scan over x [" + m(b.x0) + ", " + m(b.x1) + "] y [" + m(b.y0) + ", " +
                             m(b.y1) + "] m would grow the map from " + std::to_string(box_.width()) + " x " +
                             std::to_string(box_.height()) + " to " + std::to_string(n.width()) + " x " +
                             std::to_string(n.height()) + " cells, over the limit of " +
                             std::to_string(static_cast<long>(kMaxMapCells)) +
                             ": a pose far from the rest of the map (bad odometry?)");
  }

  // The tiles move to the new index as they are (no sum is copied).
  const CellBox nt = tilesCovering(n);
  std::vector<Tile> tiles(static_cast<size_t>(nt.width()) * nt.height());
  for (int ty = tile_box_.y0; ty < tile_box_.y1; ty++)
    for (int tx = tile_box_.x0; tx < tile_box_.x1; tx++)
      tiles[static_cast<size_t>(ty - nt.y0) * nt.width() + (tx - nt.x0)] = std::move(
          tiles_[static_cast<size_t>(ty - tile_box_.y0) * tile_box_.width() + (tx - tile_box_.x0)]);
  tiles_.swap(tiles);
  tile_box_ = nt;
  box_ = n;

  // The MRPT grid starts over at 0.5 (cell value 0 = a zero sum); only tiles hold non-zeros.
  grid_.setSize(static_cast<float>(n.x0 * resolution_), static_cast<float>(n.x1 * resolution_),
                static_cast<float>(n.y0 * resolution_), static_cast<float>(n.y1 * resolution_),
                static_cast<float>(resolution_), 0.5f);
  if (static_cast<int>(grid_.getSizeX()) != n.width() || static_cast<int>(grid_.getSizeY()) != n.height())
    throw std::logic_error("map: MRPT grid size differs from the summed grid");
  for (int ty = tile_box_.y0; ty < tile_box_.y1; ty++)
    for (int tx = tile_box_.x0; tx < tile_box_.x1; tx++) mirrorTile(tx, ty);
}

size_t SummedGrid::bytes() const
{
  return tile_count_ * kTileCells * sizeof(int32_t) + tiles_.size() * sizeof(Tile) +
         grid_.getRawMap().size();
}

}  // namespace swslam::map
