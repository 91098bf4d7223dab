#include <swslam/correlative/search_setup.h>

#include <cmath>

namespace swslam::correlative
{
ScorePyramid searchPyramid(const std::vector<Ray>& reference, const CorrelativeParams& p)
{
  const int depth = depthForWindow(p.window_xy, p.resolution);
  std::vector<Eigen::Vector2d> hits, origins;
  hits.reserve(reference.size());
  for (const auto& r : reference)
  {
    hits.push_back(r.hit);
    if (origins.empty() || r.origin != origins.back()) origins.push_back(r.origin);
  }
  // The pyramid's budget shared by its levels: a grid too large for it is refused before it is built.
  auto grid = buildScoreGrid(hits, p.resolution, p.sigma, (1 << depth) - 1, origins,
                             kMaxPyramidCells / (static_cast<size_t>(depth) + 1));
  if (p.free_space_score < 0)
    markFreeSpace(grid, reference, static_cast<int>(std::lround(255 * p.free_space_score)));
  return ScorePyramid(std::move(grid), depth);
}

std::vector<Ray> scanRays(const sensor::Scan& scan, double max_range)
{
  std::vector<Ray> rays;
  rays.reserve(scan.points.size());
  for (const auto& q : scan.points)
    if (q.norm() <= max_range) rays.push_back({Eigen::Vector2d::Zero(), q});
  return rays;
}

SearchWindow searchWindow(const CorrelativeParams& p, const mrpt::poses::CPose2D& guess)
{
  SearchWindow w;
  w.centre = {guess.x(), guess.y(), guess.phi()};
  w.half_xy = p.window_xy;
  w.half_theta = p.window_theta;
  w.theta_step = p.theta_step;
  w.cost_per_m = p.cost_per_m;
  w.cost_per_rad = p.cost_per_rad;
  return w;
}

}  // namespace swslam::correlative
