#include <swslam/localize/relocalizer.h>

#include <swslam/localize/map_score_grid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::localize
{
namespace
{
correlative::ScorePyramid mapPyramid(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh,
                                     double free_thresh)
{
  // The kernel is one cell wide: the map's cells are the search's translation step.
  // The pyramid's budget shared by its levels, each the base's size: refused before any is built.
  correlative::ScoreGrid base =
      occupancyScoreGrid(grid, occupied_thresh, free_thresh, grid.getResolution(), -255, (1 << kPyramidDepth) - 1,
                         correlative::kMaxPyramidCells / (kPyramidDepth + 1));
  if (base.cells.empty()) throw std::invalid_argument("the map has no occupied cell to localize against");
  return correlative::ScorePyramid(std::move(base), kPyramidDepth);
}

/** Windows of at most kMaxWindowCells cells a side that cover the grid's data. */
std::vector<correlative::SearchWindow> coveringWindows(const correlative::ScoreGrid& g, double theta_step)
{
  const double res = g.resolution;
  const double x0 = g.origin.x() + g.pad_cells * res, y0 = g.origin.y() + g.pad_cells * res;
  const double w = (g.width - g.pad_cells) * res, h = (g.height - g.pad_cells) * res;
  const double max_side = 2.0 * (correlative::kMaxWindowCells - 1) * res;
  const int nx = std::max(1, static_cast<int>(std::ceil(w / max_side)));
  const int ny = std::max(1, static_cast<int>(std::ceil(h / max_side)));
  std::vector<correlative::SearchWindow> out;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
    {
      correlative::SearchWindow win;
      win.centre = {x0 + (i + 0.5) * w / nx, y0 + (j + 0.5) * h / ny, 0};
      win.half_xy = 0.5 * std::max(w / nx, h / ny) + res;
      win.half_theta = M_PI;
      win.theta_step = theta_step;
      out.push_back(win);
    }
  return out;
}
}  // namespace

Relocalizer::Relocalizer(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh, double free_thresh,
                         const LocalizationParams& params)
    : params_(params), pyramid_(mapPyramid(grid, occupied_thresh, free_thresh))
{
  windows_ = coveringWindows(pyramid_.levels[0], params.theta_step);
}

std::optional<correlative::SearchResult> Relocalizer::best(const std::vector<Eigen::Vector2d>& points,
                                                           double min_score,
                                                           const std::optional<Eigen::Vector2d>& exclude) const
{
  std::optional<correlative::SearchResult> out;
  for (correlative::SearchWindow w : windows_)
  {
    if (exclude)
    {
      w.exclude_xy = *exclude;
      w.exclude_radius = params_.ambiguity_radius;
    }
    // A window searched after a better result elsewhere needs only to beat it.
    const double floor = out ? out->objective : -std::numeric_limits<double>::infinity();
    if (auto r = correlative::searchBranchAndBound(pyramid_, points, w, min_score, floor)) out = r;
  }
  return out;
}

std::optional<PlaceCandidate> Relocalizer::find(const std::vector<Eigen::Vector2d>& points) const
{
  if (points.empty()) return std::nullopt;
  const auto first = best(points, params_.min_score, std::nullopt);
  if (!first) return std::nullopt;
  PlaceCandidate c;
  c.pose = first->pose;
  c.score = first->score;
  // The runner-up needs only to be found if it is close enough to make the place ambiguous.
  const double floor = std::max(1e-6, params_.max_second_ratio * first->score);
  if (const auto second = best(points, floor, Eigen::Vector2d(first->pose.x(), first->pose.y())))
    c.second = second->score;
  c.distinct = c.second <= params_.max_second_ratio * c.score;
  return c;
}

}  // namespace swslam::localize
