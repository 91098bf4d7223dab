#pragma once
// Per-scan figures of a run (stats.csv) and the run's summary in the form of the paper's
// Table I (nodes, constraints, distance, average and maximum time per module, ATE/RPE).

#include <swslam/tracking/local_tracker.h>

#include <optional>
#include <string>
#include <vector>

namespace swslam::system
{
/** One row of stats.csv: one input scan. graph_ms and map_ms are the time the graph and map
 * threads spent on work this scan caused (its new node, loops, optimizations, re-insertion). */
struct ScanStats
{
  size_t scan = 0;
  double timestamp = 0;  ///< [s]
  tracking::TrackingSource source = tracking::TrackingSource::First;
  size_t valid_rays = 0, correspondences = 0;
  double match_sq_residuals = 0;   ///< PLICP's sum of squared point-to-line distances [m^2]
  double active_sq_residuals = 0;  ///< the latest optimization's sum of w r^2 (eq. 11, Fig. 7)
  double match_ms = 0, tracking_ms = 0, graph_ms = 0, map_ms = 0;
  size_t keyframe = 0;
  bool new_node = false;
  size_t loops = 0;  ///< loop edges accepted for this scan's node
  bool full_optimization = false;
  size_t switched_off = 0;  ///< robustified edges the latest optimization for this scan switched off
  int ambiguous = 0;      ///< directions the scan's match could not decide (TrackingStep::ambiguous)
  int prior_decided = 0;  ///< of those, the ones the prediction decided (TrackingStep::prior_decided)

  /** The prediction, not the scans alone, placed this scan: by fallback or along a direction. */
  bool placedByPrediction() const { return tracking::isFallback(source) || prior_decided > 0; }
};

/** stats.csv text: a header line, then one line per scan. */
std::string formatStatsCsv(const std::vector<ScanStats>& rows);

/** The rows of a stats.csv that formatStatsCsv wrote (or one written before its last column,
 * prior_decided, existed: read as 0). Throws std::runtime_error "stats.csv: cannot open
 * '<path>'", or "stats.csv: '<path>' line L: ..." naming the header's problem or the column
 * of the first value that is missing, malformed or not finite. */
std::vector<ScanStats> readStatsCsv(const std::string& path);

/** Average and maximum of the non-zero times of one module [ms]. */
struct TimeSummary
{
  size_t count = 0;
  double avg_ms = 0, max_ms = 0;
};
TimeSummary summarizeTimes(const std::vector<ScanStats>& rows, double ScanStats::*field,
                           bool include_zero);

/** The figures of the paper's Table I. */
struct RunSummary
{
  size_t scans = 0, skipped_scans = 0, nodes = 0, constraints = 0, loops = 0;
  size_t merged_nodes = 0;  ///< keyframes merged into earlier nodes (not counted in nodes)
  size_t refinement_pairs = 0, refinement_edges = 0;  ///< final refinement: pairs matched, edges added
  size_t fallback_scans = 0;  ///< scans whose pose came from odometry or constant motion
  size_t ambiguous_scans = 0;  ///< scans whose match had a weak direction or a second peak (ScanStats::ambiguous)
  size_t prior_decided_scans = 0;  ///< of those, scans the prediction decided along a direction
  double distance = 0;        ///< [m] along the keyframes, then to the last scan
  double duration = 0;        ///< [s] of sensor time
  double wall_time = 0;       ///< [s] processing time
  size_t map_bytes = 0;       ///< memory held by the map
  TimeSummary matching, tracking, graph, map;
  std::optional<double> ate_rmse;        ///< [m] with ground truth
  std::optional<double> rpe_step_rmse;   ///< [m] consecutive scans
  std::optional<double> rpe_metre_rmse;  ///< [m] pairs 1 m apart along the ground truth
};

/** Table I as aligned text lines. */
std::string formatRunSummary(const RunSummary& s);

}  // namespace swslam::system
