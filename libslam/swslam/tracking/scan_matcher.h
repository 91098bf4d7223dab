#pragma once
// Tracking's scan matcher (doc/tracking.md): a scan's match against the submap ending at the
// last keyframe, with the correlative search when the first match calls for it
// (search_policy.h), PLICP from the search's best pose, and the choice between the two. What
// tracking and the matcher benchmark (bench/matcher.h) both run.

#include <swslam/correlative/params.h>
#include <swslam/correlative/score_grid.h>
#include <swslam/correlative/search.h>
#include <swslam/plicp/plicp.h>
#include <swslam/tracking/params.h>
#include <swslam/tracking/prepared_scan.h>
#include <swslam/tracking/search_policy.h>

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace swslam::tracking
{
/** What tracking knows of a scan's pose before matching it. */
struct Prediction
{
  mrpt::poses::CPose2D guess;  ///< the scan's sensor pose in the last keyframe's sensor frame
  bool measured = false;       ///< odometry or a matched motion backs it (else it is a guess)
  double cost_per_m2 = 0;      ///< the search's steady-motion prior (steady_motion.h; 0: none)
  /** [m^2] the variance of its recent errors (infinite: unknown) */
  double variance = std::numeric_limits<double>::infinity();
};

/** What a scan is matched against: the last keyframe's scan for PLICP, and for the search the
 * score pyramid of the rays of the last keyframes, gathered and built the first time a scan is
 * searched against this submap. */
class Submap
{
 public:
  Submap(std::shared_ptr<const plicp::ReferenceScan> reference,
         std::function<std::vector<correlative::Ray>()> rays);
  const plicp::ReferenceScan& reference() const { return *reference_; }
  const correlative::ScorePyramid& pyramid(const correlative::CorrelativeParams& p) const;

 private:
  std::shared_ptr<const plicp::ReferenceScan> reference_;
  std::function<std::vector<correlative::Ray>()> rays_;
  mutable std::shared_ptr<const correlative::ScorePyramid> pyramid_;  ///< built on first use
};

/** The search's step: the search around the prediction, PLICP from its best pose, and the
 * choice between that match and the first. */
struct SearchedMatch
{
  plicp::MatchResult match;      ///< the chosen match
  bool replaced = false;         ///< the match from the search's pose won
  double first_objective = 0, searched_objective = 0;  ///< both matches' objectives (-1e9: failed or not run)
  double search_objective = -1e9;  ///< of the search's best pose itself (-1e9: nothing found)
  bool bounded_refinement = false;  ///< PLICP from the search's pose was run again within refine_correspondence_dist
  int searched_iterations = 0;      ///< PLICP iterations run from the search's pose, kept or not
  correlative::MatchComparison compared;  ///< what the choice compared (a: the first, b: the searched match)
  bool prediction_decided = false;  ///< the scans could not tell the two apart: the prediction chose
};

/** Searches the window around the prediction's guess with the submap's pyramid, runs PLICP from
 * the best pose, and keeps that match only if its objective (score on the grid less the motion
 * prior's cost) is min_score_gain above that of `first` (a failed match has none). The two
 * objectives are compared on the points that can tell the poses apart
 * (correlative::compareMatches): a point the keyframes never saw around, at one pose, is left
 * out when at the other it lies on a surface that goes on past it, so the pose that pulls such
 * points onto seen walls gains nothing by it. If the match from the best pose ends at a lower
 * objective than the best pose's own (PLICP against the keyframe alone left the search's
 * basin), PLICP runs again from the best pose with refine_correspondence_dist as its
 * correspondence radius, and the higher-scoring of the two is the searched match. Where the
 * searched match has almost no information along its difference from the first
 * (predictionChoice, prediction_decides_share), the prediction chooses instead of the
 * objectives. Nothing found, or a best pose in the first match's basin (within 1.5 cells and
 * 1.5 angle steps), keeps `first` without a second match. */
SearchedMatch searchAndChoose(const Submap& submap, const PreparedScan& scan, const Prediction& prediction,
                              const plicp::MatchResult& first, const TrackingParams& tracking,
                              const plicp::PlicpParams& plicp, const correlative::CorrelativeParams& search);

/** One scan's match. */
struct ScanMatch
{
  plicp::MatchResult match;  ///< the kept match, in the last keyframe's sensor frame (failed: none)
  bool searched = false;     ///< the correlative search ran
  bool replaced = false;     ///< the match from the search's pose was kept
  bool unmatched = false;    ///< the search's choice explained too few rays: the match is failed on purpose
  bool prediction_chose = false;  ///< the scans could not tell the first and the searched match apart
  /** A second peak of the search's objective of similar height, away from the kept match's
   * own: its offset from the match (sensor frame [x, y, theta]). */
  std::optional<Eigen::Vector3d> second_peak;
  int iterations = 0;  ///< PLICP iterations of every run
};

class ScanMatcher
{
 public:
  ScanMatcher(const TrackingParams& tracking, const plicp::PlicpParams& plicp,
              const correlative::CorrelativeParams& search);

  /** Matches `scan` against the submap from the prediction; searches when the first match
   * calls for it (searchTrigger, searchNeeded; a guess nothing measured is searched before
   * any PLICP match, searchFirst), then keeps what afterSearch says. Once
   * trust_prediction_after scans in a row confirmed their predictions, a match that stays on
   * its prediction is kept even with little overlap, until a match fails or moves its guess:
   * the surroundings are new or changed (a door swung shut), which the submap cannot explain
   * and the search would explain elsewhere. */
  ScanMatch match(const Submap& submap, const PreparedScan& scan, const Prediction& prediction);

 private:
  /** After a search: a second peak of the search's objective of similar height, away from the
   * match's own (correlative/peaks.h). */
  std::optional<Eigen::Vector3d> secondPeak(const Submap& submap, const PreparedScan& scan,
                                            const Prediction& prediction, const plicp::MatchResult& m) const;

  TrackingParams tracking_;
  plicp::PlicpParams plicp_;
  correlative::CorrelativeParams search_;
  size_t confirmed_in_a_row_ = 0;  ///< scans in a row whose match confirmed the prediction
};

}  // namespace swslam::tracking
