#include <swslam/tracking/scan_matcher.h>

#include <swslam/correlative/peaks.h>
#include <swslam/correlative/search.h>
#include <swslam/correlative/search_setup.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace swslam::tracking
{
using mrpt::poses::CPose2D;

namespace
{
Eigen::Vector3d vec(const CPose2D& p) { return {p.x(), p.y(), p.phi()}; }
double angleDiff(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }
}  // namespace

Submap::Submap(std::shared_ptr<const plicp::ReferenceScan> reference,
               std::function<std::vector<correlative::Ray>()> rays)
    : reference_(std::move(reference)), rays_(std::move(rays))
{
}

const correlative::ScorePyramid& Submap::pyramid(const correlative::CorrelativeParams& p) const
{
  if (!pyramid_) pyramid_ = std::make_shared<const correlative::ScorePyramid>(correlative::searchPyramid(rays_(), p));
  return *pyramid_;
}

SearchedMatch searchAndChoose(const Submap& submap, const PreparedScan& scan, const Prediction& prediction,
                              const plicp::MatchResult& first, const TrackingParams& tracking,
                              const plicp::PlicpParams& plicp, const correlative::CorrelativeParams& search)
{
  SearchedMatch out;
  out.match = first;
  const auto& points = scan.searchPoints();
  const correlative::ScorePyramid& pyramid = submap.pyramid(search);
  const auto& grid = pyramid.levels.front();
  correlative::SearchWindow w = correlative::searchWindow(search, prediction.guess);
  w.cost_per_m2 = prediction.cost_per_m2;
  auto objectiveOf = [&](const plicp::MatchResult& m) {
    return m.ok() ? correlative::objective(w, correlative::scoreAt(grid, points, vec(m.pose)), vec(m.pose)) : -1e9;
  };
  out.first_objective = objectiveOf(first);
  out.searched_objective = -1e9;
  // No floor at the first match's objective: PLICP from a lattice pose that scores below the
  // first match may still end above it (doc/notes/plicp.md says what the floor did to the corridor).
  const auto best = correlative::searchBranchAndBound(pyramid, points, w, search.min_score);
  if (!best) return out;
  out.search_objective = best->objective;
  if (first.ok() && (best->pose.head<2>() - vec(first.pose).head<2>()).norm() < 1.5 * search.resolution &&
      angleDiff(best->pose.z(), first.pose.phi()) < 1.5 * search.theta_step)
    return out;
  const CPose2D search_pose(best->pose.x(), best->pose.y(), best->pose.z());
  plicp::MatchResult second = plicp::matchScans(submap.reference(), scan.scan(), search_pose, plicp);
  out.searched_iterations = second.iterations;
  out.searched_objective = objectiveOf(second);
  // PLICP (against the keyframe alone) may leave the search's basin for a pose the grid scores
  // lower than the search's own: then refine again within a few cells of the search's pose,
  // and keep the better of the two by the objective.
  if (tracking.refine_correspondence_dist > 0 && out.searched_objective < best->objective)
  {
    plicp::PlicpParams bounded = plicp;
    bounded.max_correspondence_dist = std::min(plicp.max_correspondence_dist, tracking.refine_correspondence_dist);
    const plicp::MatchResult local = plicp::matchScans(submap.reference(), scan.scan(), search_pose, bounded);
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
    out.compared = correlative::compareMatches(grid, points, w, vec(first.pose), vec(second.pose),
                                               tracking.common_points_fraction, tracking.surface_goes_on_ratio);
  // Where the scans cannot tell the two apart, neither can their objectives: the prediction
  // chooses.
  if (first.ok() && second.ok())
  {
    const PredictionChoice who =
        predictionChoice(vec(first.pose), vec(second.pose), vec(prediction.guess), second.covariance,
                         scan.rotationLength(), tracking.prediction_decides_share, prediction.variance);
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
  if (second.ok() && out.compared.b >= out.compared.a + tracking.min_score_gain)
  {
    out.match = second;
    out.replaced = true;
  }
  return out;
}

ScanMatcher::ScanMatcher(const TrackingParams& tracking, const plicp::PlicpParams& plicp,
                         const correlative::CorrelativeParams& search)
    : tracking_(tracking), plicp_(plicp), search_(search)
{
}

ScanMatch ScanMatcher::match(const Submap& submap, const PreparedScan& scan, const Prediction& prediction)
{
  const CPose2D& guess = prediction.guess;
  // A prediction that no matched motion or odometry backs (a run's first match: "no motion")
  // is a guess, not a measurement. Along a corridor PLICP keeps it at any speed, so the
  // search decides, and PLICP runs from the search's pose alone (from the guess only if the
  // search finds no match).
  const bool search_first = search_.enabled && searchFirst(prediction.measured, tracking_.search_first_match);
  ScanMatch out;
  plicp::MatchResult first = search_first ? notRun(guess) : plicp::matchScans(submap.reference(), scan.scan(), guess, plicp_);
  out.match = first;
  out.iterations = first.iterations;
  if (!search_.enabled) return out;
  const SearchTrigger why = searchTrigger(first, guess, tracking_);
  const bool proven = tracking_.trust_prediction_after > 0 &&
                      confirmed_in_a_row_ >= static_cast<size_t>(tracking_.trust_prediction_after);
  // The count goes on through scans that lost only overlap: a door passes by over several of them.
  if (why == SearchTrigger::None) confirmed_in_a_row_++;
  if (!searchNeeded(why, prediction.measured, tracking_.search_first_match, proven)) return out;
  confirmed_in_a_row_ = 0;
  out.searched = true;
  SearchedMatch s = searchAndChoose(submap, scan, prediction, first, tracking_, plicp_, search_);
  out.iterations += s.searched_iterations;
  out.prediction_chose = s.prediction_decided;
  if (search_first && !s.replaced)
  {
    s.match = first = plicp::matchScans(submap.reference(), scan.scan(), guess, plicp_);
    out.iterations += first.iterations;
    out.match = first;
  }
  // A first match that stayed on its prediction lost only overlap: an object close in front
  // of the sensor hides the surroundings, and the search may put that object on a wall of the
  // map far away. The search's match replaces it only if it explains more of the scan than a
  // match that only stands in for a failed or moved one must; else the first match stays.
  switch (afterSearch(why, s.match, s.replaced, tracking_))
  {
    case AfterSearch::KeepFirst:
      return out;
    case AfterSearch::Unmatched:
      // Neither the prediction nor the search explains the scan: an odd scan (someone in front
      // of the sensor) or surroundings the keyframes never saw. It is unmatched rather than a
      // confident wrong pose: the prediction carries it.
      out.match = s.match;
      out.match.status = plicp::MatchStatus::TooFewCorrespondences;
      out.match.message = "the search's best match has " + std::to_string(s.match.inliers) + " inliers of " +
                          std::to_string(s.match.cur_valid_rays) + " valid rays (searched_min_inlier_fraction)";
      out.unmatched = true;
      return out;
    case AfterSearch::Chosen:
      break;
  }
  out.match = s.match;
  out.replaced = s.replaced;
  if (s.match.ok()) out.second_peak = secondPeak(submap, scan, prediction, s.match);
  return out;
}

std::optional<Eigen::Vector3d> ScanMatcher::secondPeak(const Submap& submap, const PreparedScan& scan,
                                                       const Prediction& prediction, const plicp::MatchResult& m) const
{
  correlative::SearchWindow w = correlative::searchWindow(search_, prediction.guess);
  w.cost_per_m2 = prediction.cost_per_m2;
  const Eigen::Vector3d chosen = vec(m.pose);
  const auto peak = correlative::secondPeak(submap.pyramid(search_), scan.searchPoints(), w, chosen,
                                            correlative::peakRadius(search_.sigma, search_.resolution),
                                            search_.min_score, tracking_.min_score_gain);
  if (!peak || !peak->similar) return std::nullopt;
  Eigen::Vector3d d = peak->peak.pose - chosen;
  d.z() = std::remainder(d.z(), 2 * M_PI);
  return d;
}

}  // namespace swslam::tracking
