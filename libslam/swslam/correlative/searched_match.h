#pragma once
// Re-alignment of a tracking match whose prediction failed (doc/tracking.md): a correlative
// search by branch and bound over a wide window around the prediction, PLICP from its best
// pose, and the better of the two matches by the search's score.

#include <swslam/correlative/params.h>
#include <swslam/correlative/score_grid.h>
#include <swslam/correlative/search.h>
#include <swslam/plicp/plicp.h>

#include <mrpt/poses/CPose2D.h>

#include <limits>
#include <vector>

namespace swslam::correlative
{
/** The score pyramid of reference rays (in the reference sensor frame), deep enough for the
 * search window: the kernels of their hits, and free_space_score on the cells they cross. The
 * caller leaves out rays longer than max_range. */
ScorePyramid searchPyramid(const std::vector<Ray>& reference,
                                        const CorrelativeParams& p);

/** The search window of the parameters (window_xy, window_theta, theta_step, motion prior)
 * centred on `guess` (a sensor pose in the reference sensor frame). */
SearchWindow searchWindow(const CorrelativeParams& p, const mrpt::poses::CPose2D& guess);

/** The rays of one scan seen from its own sensor (origin 0), up to max_range: the reference
 * of a search against that scan alone. */
std::vector<Ray> scanRays(const sensor::Scan& scan, double max_range);

/** Why a tracking match calls for the search. */
enum class SearchTrigger
{
  None,        ///< the match confirms its prediction
  Failed,      ///< the match failed
  Moved,       ///< it moved the guess (sensor frame) by more than trigger_correction_xy or _theta
  LowOverlap,  ///< it stayed near the guess with fewer than trigger_inlier_fraction of the
               ///< scan's points as inliers
};
SearchTrigger searchTrigger(const plicp::MatchResult& m, const mrpt::poses::CPose2D& guess,
                            const CorrelativeParams& p);

/** Whether tracking searches after a first match that ended with `why`. A guess that nothing
 * measured (no odometry, no matched motion: a run's first match, or a pair with no
 * prediction) is always searched when `search_guesses` is on (tracking's search_first_match):
 * along a corridor PLICP keeps such a guess at any speed, its match moving nothing and keeping
 * most of its points as inliers. A measured prediction is searched when the trigger is not
 * None, except for little overlap on a prediction that the last scans confirmed (`proven`). */
bool searchNeeded(SearchTrigger why, bool guess_measured, bool search_guesses, bool proven);

/** Whether a pair is searched before any PLICP match: its guess is one that searchNeeded()
 * always searches (nothing measured it, `search_guesses` on). PLICP then runs only from the
 * search's best pose (searchAndMatch() with notRun() as the first match), and from the guess
 * only when that gives no match. The guess is no better a start than the search's pose: PLICP
 * from it as well cost a third of a searched pair's time from identity and changed few
 * results (doc/plicp.md). */
bool searchFirst(bool guess_measured, bool search_guesses);

/** The first match of a pair searched first: not run, at the guess (not ok: searchAndMatch()
 * has no first match to keep, and replaces it with any match it finds). */
plicp::MatchResult notRun(const mrpt::poses::CPose2D& guess);

/** The objectives the choice between a first and a searched match compares (compareMatches). */
struct MatchComparison
{
  double first = 0, searched = 0;
  size_t common_points = 0;  ///< the points compared on (0: all of them)
};

struct SearchedMatch
{
  plicp::MatchResult match;      ///< the chosen match
  bool replaced = false;  ///< the match from the search's pose won
  double first_objective = 0, searched_objective = 0;  ///< both matches' objectives (-1e9: failed or not run)
  double search_objective = -1e9;  ///< of the search's best pose itself (-1e9: nothing found)
  bool bounded_refinement = false;  ///< PLICP from the search's pose was run again within refine_correspondence_dist
  int searched_iterations = 0;      ///< PLICP iterations run from the search's pose, kept or not
  MatchComparison compared;  ///< what the choice compared (the objectives above when a match failed)
  bool prediction_decided = false;  ///< the scans could not tell the two apart: the prediction chose (predictionChoice)
};

/** The share of a match's information along a pose difference, against its strongest
 * direction's: u' I u / lambda_max(I), u the unit difference and I the inverse of the
 * covariance, both over (x, y, length * theta) (a turn counted as the arc it moves points at
 * `length` by: sensor::rotationLength). In [0, 1]. 1 (fully informed) for a zero or
 * non-finite difference, a covariance that is not positive definite, or a length that is not
 * positive. */
double informationShare(const Eigen::Matrix3d& covariance, const Eigen::Vector3d& difference, double length);

/** Who chooses between a first and a searched match. */
enum class PredictionChoice
{
  Scans,     ///< the searched match is informed along the difference, or the prediction is too
             ///< uncertain to tell the two apart: the objectives choose
  First,     ///< the scans cannot tell the two apart, and the first lies nearer the prediction
  Searched,  ///< ... and the searched one does
};

/** How far apart, in standard deviations of the prediction's recent errors, two matches must
 * lie for the prediction to tell them apart (predictionChoice). */
constexpr double kPredictionSigmas = 3;

/** Where the scans cannot tell two matches apart, the prediction chooses: when the searched
 * match's informationShare along their difference is under `share`, and the two lie more
 * than kPredictionSigmas standard deviations of the prediction apart (`prediction_variance`
 * [m^2], its recent errors: a prediction no better than the difference between them tells
 * nothing either), the one nearer the prediction along that difference (the first on a tie;
 * over (x, y, length * theta), theta differences wrapped). A pair of scans along a corridor
 * fixes neither match along it, and a search's grid scores a pose that pulls the scan back
 * into what the keyframes saw higher (doc/tracking.md, "The prediction chooses where the scans
 * cannot"). The share is measured as tracking measures weak directions (tracking/ambiguity.h),
 * which lies a layer above this module. */
PredictionChoice predictionChoice(const Eigen::Vector3d& first, const Eigen::Vector3d& searched,
                                  const Eigen::Vector3d& prediction, const Eigen::Matrix3d& searched_covariance,
                                  double length, double share, double prediction_variance);

/** Two poses' objectives (score on the grid less the window's motion prior) as the choice
 * between a first and a searched match compares them: on the points that can tell them apart
 * (commonScores, with goes_on_ratio) when at least common_points_fraction of the points are
 * (and some are), else on all the points (scoreAt). */
MatchComparison compareMatches(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
                               const SearchWindow& w, const Eigen::Vector3d& first,
                               const Eigen::Vector3d& searched, double common_points_fraction,
                               double goes_on_ratio);

/** Searches the window around `guess` (the current sensor pose in the reference sensor
 * frame, as for matchScans) with the reference's pyramid, runs PLICP from the best pose, and
 * keeps that match only if its objective (score on the grid less the motion prior's cost) is
 * min_score_gain above that of `first` (a failed match has none). The two objectives are
 * compared on the points that can tell the poses apart (compareMatches): a point the
 * keyframes never saw around, at one pose, is left out when at the other it lies on a surface
 * that goes on past it, so the pose that pulls such points onto seen walls gains nothing by
 * it. If the match from the best pose ends at a lower objective than the best pose's own
 * (PLICP against the keyframe alone left the search's basin), PLICP runs again from the best
 * pose with refine_correspondence_dist as its correspondence radius, and the higher-scoring
 * of the two is the searched match. Where the searched match has almost no information
 * along its difference from the first (predictionChoice, prediction_decides_share), the
 * prediction (of variance `prediction_variance` [m^2]; infinite: unknown) chooses instead of
 * the objectives.
 * Nothing found, or a best
 * pose in the first match's basin (within 1.5 cells and 1.5 angle steps), keeps `first`
 * without a second match. `cost_per_m2` adds a quadratic translation cost to the window's
 * motion prior (the steady-motion prior, tracking/steady_motion.h), in the search and in
 * both objectives. */
SearchedMatch searchAndMatch(const plicp::ReferenceScan& reference,
                             const ScorePyramid& pyramid, const sensor::Scan& cur,
                             const mrpt::poses::CPose2D& guess, const plicp::MatchResult& first,
                             const CorrelativeParams& p, const plicp::PlicpParams& plicp,
                             double cost_per_m2 = 0,
                             double prediction_variance = std::numeric_limits<double>::infinity());

/** What tracking keeps after searchAndMatch() (LocalTracker::matchLast; the matcher bench
 * asks the same). */
enum class AfterSearch
{
  KeepFirst,  ///< the first match stays: it stayed on its prediction and lost only overlap,
              ///< and the search's match that replaced it explains too little of the scan
              ///< (an object close in front of the sensor put on a wall elsewhere)
  Unmatched,  ///< neither explains the scan: the chosen match has too few inliers, and the
              ///< prediction carries the scan
  Chosen,     ///< the search's choice (SearchedMatch::match: the first, or the one it found)
};
/** The rule: a replacement of a first match searched for its little overlap (why ==
 * LowOverlap) needs overlap_min_inlier_fraction of the valid rays as inliers, else KeepFirst;
 * then a chosen match with fewer than min_inlier_fraction of its valid rays as inliers is
 * Unmatched ([tracking] overlap_search_min_inlier_fraction, searched_min_inlier_fraction). */
AfterSearch afterSearch(SearchTrigger why, const SearchedMatch& s, double overlap_min_inlier_fraction,
                        double min_inlier_fraction);

}  // namespace swslam::correlative
