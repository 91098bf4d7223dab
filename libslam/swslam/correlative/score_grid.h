#pragma once
// The score grid of correlative scan matching (Olson 2009): each cell holds how well a point
// there fits a reference point set, exp(-d^2 / 2 sigma^2) with d the distance from the cell's
// centre to the nearest reference point, quantized to 0..255; optionally a negative value
// where the reference's rays saw free space. Its max-pyramid gives the upper bounds of the
// branch-and-bound search (search.h).

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace swslam::correlative
{
/** The memory budget of a search: a score pyramid (all its levels, 2 bytes a cell) holds at
 * most this many cells, 1 GB (as the rawlog decoder's budget): at the default 0.1 m
 * resolution and window (7 levels), a reference 870 m across. Past it buildScoreGrid and
 * ScorePyramid throw std::length_error instead of allocating; no input (a sensor pose of
 * 1e30, a reference spread over kilometres) makes them allocate more or index outside. */
constexpr size_t kMaxPyramidCells = size_t(1) << 29;

/** Cell coordinates are clamped to +-kFarCell: a cell that far is outside every grid (none is
 * that wide), and the clamp keeps the arithmetic on them (offsets, 2 a - b) within int. */
constexpr int kFarCell = 1 << 29;

/** floor(v) as a cell coordinate, clamped to [-kFarCell, kFarCell] (NaN: kFarCell), so that
 * no coordinate, however far, overflows the conversion to int. */
inline int cellFloor(double v)
{
  if (!(v < kFarCell)) return kFarCell;
  if (v < -kFarCell) return -kFarCell;
  const int i = static_cast<int>(v);
  return i - (v < i);
}

struct ScoreGrid
{
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< lower-left corner of cell (0, 0)
  double resolution = 0.1;                           ///< [m] cell side
  int width = 0, height = 0;
  int pad_cells = 0;           ///< empty cells below the data's reach, on the low x and y sides
  std::vector<int16_t> cells;  ///< row-major, cell (x, y) at y * width + x

  /** The cell's value, 0 outside the grid. */
  int at(int x, int y) const
  {
    if (x < 0 || y < 0 || x >= width || y >= height) return 0;
    return cells[static_cast<size_t>(y) * width + x];
  }
  /** The cell holding point p (may be outside the grid; cellFloor's clamp far away). */
  Eigen::Vector2i cellOf(const Eigen::Vector2d& p) const
  {
    return {cellFloor((p.x() - origin.x()) / resolution), cellFloor((p.y() - origin.y()) / resolution)};
  }
};

/** The grid of `points` with cells of `resolution` and kernel `sigma`: cell value
 * round(255 exp(-d^2 / 2 sigma^2)), d from the cell's centre to the nearest point, and 0
 * beyond 3 sigma. It covers the bounding box of the points and of `cover` (where rays start,
 * for markFreeSpace) plus 3 sigma, and `pad_cells` more cells on its low sides (x and y),
 * where the pyramid's windows start (ScorePyramid). Points that are not finite are left out;
 * no points give an empty grid. Its size is computed in double and checked before any
 * allocation: a grid of more than `max_cells` cells throws std::length_error naming its
 * size and extent. */
ScoreGrid buildScoreGrid(const std::vector<Eigen::Vector2d>& points, double resolution, double sigma,
                         int pad_cells = 0, const std::vector<Eigen::Vector2d>& cover = {},
                         size_t max_cells = kMaxPyramidCells);

/** A reference observation: the sensor at `origin` saw a surface at `hit`. */
struct Ray
{
  Eigen::Vector2d origin, hit;
};

/** Gives `free_value` (<= 0) to the cells of value 0 that the rays cross: the cells of the
 * points origin + s (hit - origin) / |hit - origin| for s = 0, resolution/2, ... < |hit -
 * origin|. Cells near a hit keep their kernel value; points outside the grid are skipped (only
 * the part of a ray inside the grid is walked, so a ray of any length costs at most the
 * grid's diagonal; one not finite is skipped). A scan point in such a cell contradicts the
 * reference (it saw through there). */
void markFreeSpace(ScoreGrid& grid, const std::vector<Ray>& rays, int free_value);

/** Level h of the pyramid has the grid's frame and size; its cell (x, y) is the largest
 * value of level 0 over [x, x + 2^h) x [y, y + 2^h) (0 outside the grid). The base grid needs
 * 2^depth - 1 cells of padding on its low sides (buildScoreGrid's pad_cells) so that no window
 * reaching data starts outside it; with less, the constructor throws std::invalid_argument. A
 * window that starts past the high sides reaches no data, so those need none. Levels of more
 * than kMaxPyramidCells cells in all throw std::length_error. */
struct ScorePyramid
{
  std::vector<ScoreGrid> levels;  ///< levels[0] is the base grid
  ScorePyramid(ScoreGrid base, int depth);
  int depth() const { return static_cast<int>(levels.size()) - 1; }
};

/** The points kept for a search: within `max_range` of the origin, and each at least
 * `min_spacing` from the previously kept one (in scan order). */
std::vector<Eigen::Vector2d> thinPoints(const std::vector<Eigen::Vector2d>& points,
                                        double min_spacing, double max_range);

}  // namespace swslam::correlative
