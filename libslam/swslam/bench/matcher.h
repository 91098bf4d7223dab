#pragma once
// Benchmark of scan matchers on consecutive scan pairs with reference poses: our PLICP
// against MRPT's CICP (classic and Levenberg-Marquardt), each from identity and from the
// reference relative pose. Used by apps/swslam-bench-matcher.

#include <swslam/correlative/params.h>
#include <swslam/io/scans_with_truth.h>
#include <swslam/plicp/plicp.h>
#include <swslam/tracking/params.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>
#include <vector>

namespace swslam::bench
{
/** Figures of one method from one initial guess, over all pairs. */
struct MatcherRow
{
  std::string method, init;
  size_t pairs = 0, failures = 0;
  size_t searched = 0;  ///< plicp+search: the pairs the correlative search ran for
  double median_us = 0, p95_us = 0, mean_iters = 0;
  double trans_median_m = 0, trans_rmse_m = 0, rot_rmse_deg = 0, frac_under_5cm = 0;
  /** Each pair's estimate of the vehicle's relative pose, in pair order, and whether the
   * match succeeded (a failed one carries its guess). */
  struct PairEstimate
  {
    mrpt::poses::CPose2D pose;
    bool ok = true;
  };
  std::vector<PairEstimate> estimates;
};

/** Runs every method (or only the one named `only`, if not empty) from each initial guess on
 * pairs (k, k + stride): `plicp`, `plicp+search` (tracking's own matcher, tracking::ScanMatcher,
 * with `search_params` and `tracking`, against the pair's first scan: the reference motion
 * counts as a measured prediction and identity as a guess; an unmatched pair fails with the
 * guess as its pose, as the prediction carries such a scan), `cicp-classic`, `cicp-lm`.
 * Errors are measured on the vehicle's relative pose.
 * Throws std::invalid_argument for an unknown method name. */
std::vector<MatcherRow> benchmarkMatchers(const io::ScansWithTruth& data, size_t stride,
                                          const plicp::PlicpParams& plicp_params,
                                          const std::string& only = "",
                                          const correlative::CorrelativeParams& search_params = {},
                                          const tracking::TrackingParams& tracking = {});

/** The work every PLICP match at full resolution does before its first closed-form step, on
 * the pairs of benchmarkMatchers() from the reference guess: both scans converted
 * (scanFromObservation), the reference scan's index built (ReferenceScan) and one
 * correspondence search. Median microseconds of each part and of their per-pair sum: no
 * PLICP of this design matches faster than `total_us`. */
struct PlicpFloor
{
  size_t pairs = 0;
  double conversion_us = 0, index_us = 0, search_us = 0, total_us = 0;
};
PlicpFloor plicpFloor(const io::ScansWithTruth& data, size_t stride, const plicp::PlicpParams& params);

/** "plicp-floor init=reference pairs=... median_us=... conversion_us=... index_us=... search_us=...". */
std::string formatFloor(const PlicpFloor& floor);

/** What a pair that `plicp+search` searches costs at least, on the pairs of
 * benchmarkMatchers() from identity (no prediction): the PLICP match (both scans converted, the
 * reference index built, the match), the search's grid and pyramid built from the reference
 * scan, and the branch-and-bound search of the window around identity. Identity is a guess:
 * with `tracking.search_first_match` every pair is searched first and the PLICP match is the one
 * from the search's best pose (tracking::searchFirst()); else PLICP from identity comes first,
 * and `searched` counts the pairs whose match says the guess was poor (the PLICP match from the
 * search's pose that follows is then not counted). The times are medians over the searched
 * pairs, and `total_us` the median of each pair's sum of the three. */
struct SearchFloor
{
  size_t pairs = 0, searched = 0;
  double plicp_us = 0, grid_us = 0, bnb_us = 0, total_us = 0;
  double evaluated_median = 0;  ///< candidates the branch and bound scored, median per pair
  /** Per pyramid level h (index h), the mean per pair of the candidates scored at it and of
   * those split into their children (correlative::SearchResult): where the search's work lies.
   * These two count the searches that found a pose (a search with none reports no counts). */
  std::vector<double> evaluated_by_level, expanded_by_level;
};
SearchFloor searchFloor(const io::ScansWithTruth& data, size_t stride, const plicp::PlicpParams& plicp_params,
                        const correlative::CorrelativeParams& search_params,
                        const tracking::TrackingParams& tracking = {});

/** "search-floor init=identity pairs=... searched=... median_us=... plicp_us=... grid_us=... bnb_us=...
 * evaluated_median=... by_level=E/X,...", the levels from the top down, E the mean candidates
 * scored and X the mean split at each. */
std::string formatSearchFloor(const SearchFloor& floor);

/** The pairs that `plicp+search` puts 5 cm or more from the reference from identity (its
 * benchmarkMatchers() row `from_identity`, on the same data and stride; std::invalid_argument
 * for another row), and in how many of them the pair's own scans support the reference. Such a
 * miss is *supported* when PLICP started at the reference motion stays within 5 cm of it (the
 * pair has an optimum there) and that match beats PLICP's started at the chosen pose by
 * either measure a choice could use: more inliers, or a higher score on the search's grid of
 * the reference scan (correlative::scoreAt, no motion prior). In the other misses the pair
 * favours the chosen pose, or ties, or has no optimum at the reference: no choice made from
 * the pair alone mends them. `best_share`: the share under 5 cm with every supported miss
 * mended, an upper bound for any such choice. */
struct MissExplanation
{
  size_t pairs = 0, misses = 0, supported = 0;
  double best_share = 0;
};
MissExplanation explainMisses(const io::ScansWithTruth& data, size_t stride, const MatcherRow& from_identity,
                              const plicp::PlicpParams& plicp_params,
                              const correlative::CorrelativeParams& search_params);

/** "misses        init=identity  pairs=... misses=... supported=... best_frac_under_5cm=...". */
std::string formatMisses(const MissExplanation& m);

/** One line per row: "plicp init=identity median_us=... p95_us=... ..." (plicp+search rows end
 * with "searched=N"). */
std::string formatRow(const MatcherRow& row);

}  // namespace swslam::bench
