#pragma once
// Tracking's rules around the correlative search (doc/tracking.md): when a scan's first match
// calls for the search, and what is kept after it. The search itself is the correlative
// module's; these decisions are tracking's, as Cartographer's ScanMatch owns "search, then
// refine".

#include <swslam/plicp/plicp.h>
#include <swslam/tracking/params.h>

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

namespace swslam::tracking
{
/** Why a first match calls for the search. */
enum class SearchTrigger
{
  None,        ///< the match confirms its prediction
  Failed,      ///< the match failed
  Moved,       ///< it moved the guess (sensor frame) by more than trigger_correction_xy or _theta
  LowOverlap,  ///< it stayed near the guess with fewer than trigger_inlier_fraction of the
               ///< scan's points as inliers
};
SearchTrigger searchTrigger(const plicp::MatchResult& m, const mrpt::poses::CPose2D& guess, const TrackingParams& p);

/** Whether tracking searches after a first match that ended with `why`. A guess that nothing
 * measured (no odometry, no matched motion: a run's first match, or a pair with no
 * prediction) is always searched when `search_guesses` is on (search_first_match): along a
 * corridor PLICP keeps such a guess at any speed, its match moving nothing and keeping most of
 * its points as inliers. A measured prediction is searched when the trigger is not None,
 * except for little overlap on a prediction that the last scans confirmed (`proven`). */
bool searchNeeded(SearchTrigger why, bool guess_measured, bool search_guesses, bool proven);

/** Whether a pair is searched before any PLICP match: its guess is one that searchNeeded()
 * always searches (nothing measured it, `search_guesses` on). PLICP then runs only from the
 * search's best pose, and from the guess only when that gives no match. The guess is no
 * better a start than the search's pose: PLICP from it as well cost a third of a searched
 * pair's time from identity and changed few results (doc/notes/plicp.md). */
bool searchFirst(bool guess_measured, bool search_guesses);

/** The first match of a pair searched first: not run, at the guess (not ok: the search has no
 * first match to keep, and replaces it with any match it finds). */
plicp::MatchResult notRun(const mrpt::poses::CPose2D& guess);

/** What tracking keeps after the search. */
enum class AfterSearch
{
  KeepFirst,  ///< the first match stays: it stayed on its prediction and lost only overlap,
              ///< and the search's match that replaced it explains too little of the scan
              ///< (an object close in front of the sensor put on a wall elsewhere)
  Unmatched,  ///< neither explains the scan: the chosen match has too few inliers, and the
              ///< prediction carries the scan
  Chosen,     ///< the search's choice (the first match, or the one the search found)
};
/** The rule, for `chosen` (a match that `replaced` the first, or the first): a replacement
 * of a first match searched for its little overlap (why == LowOverlap) needs
 * overlap_search_min_inlier_fraction of the valid rays as inliers, else KeepFirst; then a
 * chosen match with fewer than searched_min_inlier_fraction of its valid rays as inliers is
 * Unmatched. */
AfterSearch afterSearch(SearchTrigger why, const plicp::MatchResult& chosen, bool replaced, const TrackingParams& p);

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
 * into what the keyframes saw higher (doc/tracking.md, "Ambiguous matches"). */
PredictionChoice predictionChoice(const Eigen::Vector3d& first, const Eigen::Vector3d& searched,
                                  const Eigen::Vector3d& prediction, const Eigen::Matrix3d& searched_covariance,
                                  double length, double share, double prediction_variance);

}  // namespace swslam::tracking
