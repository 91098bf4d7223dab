#include <swslam/correlative/searched_match.h>

#include <swslam/correlative/search.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace swslam::correlative
{
using mrpt::poses::CPose2D;

namespace
{
Eigen::Vector3d vec(const CPose2D& p) { return {p.x(), p.y(), p.phi()}; }
double angleDiff(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }
}  // namespace

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
  auto grid = buildScoreGrid(hits, p.resolution, p.sigma, (1 << depth) - 1, origins);
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

SearchWindow searchWindow(const CorrelativeParams& p, const CPose2D& guess)
{
  SearchWindow w;
  w.centre = vec(guess);
  w.half_xy = p.window_xy;
  w.half_theta = p.window_theta;
  w.theta_step = p.theta_step;
  w.cost_per_m = p.cost_per_m;
  w.cost_per_rad = p.cost_per_rad;
  return w;
}

SearchTrigger searchTrigger(const plicp::MatchResult& m, const CPose2D& guess, const CorrelativeParams& p)
{
  if (!m.ok() || m.cur_valid_rays == 0) return SearchTrigger::Failed;
  if ((m.pose.translation() - guess.translation()).norm() > p.trigger_correction_xy ||
      angleDiff(m.pose.phi(), guess.phi()) > p.trigger_correction_theta)
    return SearchTrigger::Moved;
  if (m.inliers < p.trigger_inlier_fraction * m.cur_valid_rays) return SearchTrigger::LowOverlap;
  return SearchTrigger::None;
}

bool searchNeeded(SearchTrigger why, bool guess_measured, bool search_guesses, bool proven)
{
  if (search_guesses && !guess_measured) return true;
  return why != SearchTrigger::None && !(why == SearchTrigger::LowOverlap && proven);
}

bool searchFirst(bool guess_measured, bool search_guesses) { return search_guesses && !guess_measured; }

plicp::MatchResult notRun(const CPose2D& guess)
{
  plicp::MatchResult m;
  m.status = plicp::MatchStatus::InvalidInput;
  m.pose = guess;
  m.message = "not run: the guess was searched first";
  return m;
}

MatchComparison compareMatches(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
                               const SearchWindow& w, const Eigen::Vector3d& first,
                               const Eigen::Vector3d& searched, double common_points_fraction,
                               double goes_on_ratio)
{
  MatchComparison out;
  if (common_points_fraction > 0)
  {
    const CommonScores c = commonScores(grid, points, first, searched, goes_on_ratio);
    if (c.points > 0 && c.points >= common_points_fraction * points.size())
    {
      out.first = objective(w, c.a, first);
      out.searched = objective(w, c.b, searched);
      out.common_points = c.points;
      return out;
    }
  }
  out.first = objective(w, scoreAt(grid, points, first), first);
  out.searched = objective(w, scoreAt(grid, points, searched), searched);
  return out;
}

double informationShare(const Eigen::Matrix3d& covariance, const Eigen::Vector3d& difference, double length)
{
  if (!(length > 0) || !std::isfinite(length) || !difference.allFinite() || !covariance.allFinite()) return 1.0;
  const Eigen::DiagonalMatrix<double, 3> S(1, 1, length);
  Eigen::Vector3d u = S * difference;
  if (!(u.norm() > 0)) return 1.0;
  u.normalize();
  // The information is the inverse of the covariance: its eigenvalues are the inverses of the
  // covariance's, so no inverse is formed (a near-singular direction is the strongest).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S * covariance * S);
  if (es.info() != Eigen::Success) return 1.0;
  const Eigen::Vector3d variances = es.eigenvalues();
  if (!(variances.minCoeff() > 0)) return 1.0;
  const Eigen::Vector3d along = es.eigenvectors().transpose() * u;
  double information = 0;
  for (int k = 0; k < 3; k++) information += along(k) * along(k) / variances(k);
  return std::clamp(information * variances.minCoeff(), 0.0, 1.0);
}

PredictionChoice predictionChoice(const Eigen::Vector3d& first, const Eigen::Vector3d& searched,
                                  const Eigen::Vector3d& prediction, const Eigen::Matrix3d& searched_covariance,
                                  double length, double share, double prediction_variance)
{
  auto wrapped = [](Eigen::Vector3d d) {
    d.z() = std::remainder(d.z(), 2 * M_PI);
    return d;
  };
  const Eigen::Vector3d d = wrapped(searched - first);
  if (!(share > 0) || !(informationShare(searched_covariance, d, length) < share)) return PredictionChoice::Scans;
  // informationShare accepted the length and the difference: both are finite, and d is not 0.
  const Eigen::DiagonalMatrix<double, 3> S(1, 1, length);
  const Eigen::Vector3d apart = S * d;
  if (!(apart.squaredNorm() > kPredictionSigmas * kPredictionSigmas * prediction_variance))
    return PredictionChoice::Scans;
  const Eigen::Vector3d u = apart.normalized();
  const double first_off = std::abs(u.dot(S * wrapped(first - prediction)));
  const double searched_off = std::abs(u.dot(S * wrapped(searched - prediction)));
  return first_off <= searched_off ? PredictionChoice::First : PredictionChoice::Searched;
}

SearchedMatch searchAndMatch(const plicp::ReferenceScan& reference, const ScorePyramid& pyramid,
                             const sensor::Scan& cur, const CPose2D& guess, const plicp::MatchResult& first,
                             const CorrelativeParams& p, const plicp::PlicpParams& plicp, double cost_per_m2,
                             double prediction_variance)
{
  SearchedMatch out;
  out.match = first;
  const auto points = thinPoints(cur.points, p.resolution, p.max_range);
  const auto& grid = pyramid.levels.front();
  SearchWindow w = searchWindow(p, guess);
  w.cost_per_m2 = cost_per_m2;
  auto objectiveOf = [&](const plicp::MatchResult& m) {
    return m.ok() ? objective(w, scoreAt(grid, points, vec(m.pose)), vec(m.pose)) : -1e9;
  };
  out.first_objective = objectiveOf(first);
  out.searched_objective = -1e9;
  // No floor at the first match's objective: PLICP from a lattice pose that scores below the
  // first match may still end above it (doc/plicp.md says what the floor did to the corridor).
  const auto best = searchBranchAndBound(pyramid, points, w, p.min_score);
  if (!best) return out;
  out.search_objective = best->objective;
  if (first.ok() && (best->pose.head<2>() - vec(first.pose).head<2>()).norm() < 1.5 * p.resolution &&
      angleDiff(best->pose.z(), first.pose.phi()) < 1.5 * p.theta_step)
    return out;
  const CPose2D search_pose(best->pose.x(), best->pose.y(), best->pose.z());
  plicp::MatchResult second = plicp::matchScans(reference, cur, search_pose, plicp);
  out.searched_iterations = second.iterations;
  out.searched_objective = objectiveOf(second);
  // PLICP (against the keyframe alone) may leave the search's basin for a pose the grid scores
  // lower than the search's own: then refine again within a few cells of the search's pose,
  // and keep the better of the two by the objective.
  if (p.refine_correspondence_dist > 0 && out.searched_objective < best->objective)
  {
    plicp::PlicpParams bounded = plicp;
    bounded.max_correspondence_dist = std::min(plicp.max_correspondence_dist, p.refine_correspondence_dist);
    const plicp::MatchResult local = plicp::matchScans(reference, cur, search_pose, bounded);
    out.searched_iterations += local.iterations;
    const double local_objective = objectiveOf(local);
    out.bounded_refinement = true;
    if (local_objective > out.searched_objective)
    {
      second = local;
      out.searched_objective = local_objective;
    }
  }
  out.compared = {out.first_objective, out.searched_objective, 0};
  if (first.ok() && second.ok())
    out.compared = compareMatches(grid, points, w, vec(first.pose), vec(second.pose), p.common_points_fraction,
                                  p.surface_goes_on_ratio);
  // Where the scans cannot tell the two apart, neither can their objectives: the prediction
  // chooses.
  if (first.ok() && second.ok())
  {
    const PredictionChoice who = predictionChoice(vec(first.pose), vec(second.pose), vec(guess), second.covariance,
                                                  sensor::rotationLength(cur.points), p.prediction_decides_share,
                                                  prediction_variance);
    if (who != PredictionChoice::Scans)
    {
      out.prediction_decided = true;
      if (who == PredictionChoice::Searched)
      {
        out.match = second;
        out.replaced = true;
      }
      return out;
    }
  }
  if (second.ok() && out.compared.searched >= out.compared.first + p.min_score_gain)
  {
    out.match = second;
    out.replaced = true;
  }
  return out;
}

AfterSearch afterSearch(SearchTrigger why, const SearchedMatch& s, double overlap_min_inlier_fraction,
                        double min_inlier_fraction)
{
  const plicp::MatchResult& m = s.match;
  if (s.replaced && why == SearchTrigger::LowOverlap && m.ok() &&
      m.inliers < overlap_min_inlier_fraction * m.cur_valid_rays)
    return AfterSearch::KeepFirst;
  if (m.ok() && m.inliers < min_inlier_fraction * m.cur_valid_rays) return AfterSearch::Unmatched;
  return AfterSearch::Chosen;
}

}  // namespace swslam::correlative
