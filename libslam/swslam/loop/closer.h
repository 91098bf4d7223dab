#pragma once
// Loop closure (paper sec. II.C, III.B): a node and an older one are a loop candidate when
// their ids differ by at least a gap and their graph poses are close. A candidate is verified
// by PLICP from the graph's relative pose and accepted only if the match converges, overlaps
// enough and agrees with the graph within a chi-square gate whose covariance is the match's
// plus a drift that grows with the distance travelled between the two nodes (see
// doc/loop-closure.md). An accepted pair becomes a loop edge; the caller then optimizes the
// whole graph. Pure functions: no threads, no config reading.

#include <swslam/correlative/params.h>
#include <swslam/graph/constraint.h>
#include <swslam/graph/pose_graph.h>
#include <swslam/loop/params.h>
#include <swslam/plicp/plicp.h>

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace swslam::loop
{
/** What loop closure needs of a graph node besides its pose (which is read from the graph). */
struct LoopNode
{
  size_t id = 0;
  /** The node's scan, sensor frame; its Scan::sensor_pose is the mounting on the vehicle. */
  std::shared_ptr<const plicp::ReferenceScan> scan;
  double path_length = 0;  ///< [m] distance travelled from the first node to this one
};

/** The outcome of verifying one candidate pair. */
struct LoopCheck
{
  enum class Verdict
  {
    Accepted,      ///< `edge` holds the loop edge
    MatchFailed,   ///< PLICP did not converge (status/message in `match`)
    PoorOverlap,   ///< converged, but fewer inliers than min_inlier_fraction
    GateRejected,  ///< converged, but mahalanobis2 > chi2_gate
  };
  size_t from = 0, to = 0;        ///< the older node and the new one
  double distance = 0;            ///< [m] between their graph poses
  double path_gap = 0;            ///< [m] distance travelled between them
  mrpt::poses::CPose2D predicted; ///< graph's vehicle pose of `to` seen from `from`
  plicp::MatchResult match;              ///< PLICP of `to`'s scan against `from`'s, sensor frame
  bool searched = false;          ///< `match` started from a correlative search's pose
  double inlier_fraction = 0;     ///< match.correspondences / match.cur_valid_rays
  double mahalanobis2 = std::numeric_limits<double>::infinity();  ///< when the match converged
  Verdict verdict = Verdict::MatchFailed;
  std::optional<graph::Constraint> edge;  ///< from -> to, kind Loop, only when Accepted
};
const char* toString(LoopCheck::Verdict v);

/** Candidates for node `newest`: nodes with id <= newest - min_index_gap, not merged into
 * another, whose graph pose is within max_distance and that share no edge with `newest` yet, nearest first, at most
 * max_candidates; none when disabled. With none that near and `path_length` given (metres
 * travelled to a node): the one node within max_search_radius and within 3 drift_xy_per_m
 * times the path between the two whose distance is the smallest share of that reach. One
 * linear pass over the older node poses (a distance each, no scan work). Throws
 * std::invalid_argument if `newest` is not in the graph. */
std::vector<size_t> loopCandidates(const graph::PoseGraph& graph, size_t newest, const LoopClosureParams& p,
                                   const std::function<double(size_t)>& path_length = nullptr);

/** Drift covariance of the graph's relative pose after travelling `path_gap` metres:
 * diag(sxy^2, sxy^2, sth^2), sxy = max(drift_xy_per_m * gap, min_drift_sigma_xy), sth alike. */
Eigen::Matrix3d driftCovariance(double path_gap, const LoopClosureParams& p);

/** A loop check's overlap: the match's correspondences over the new scan's valid rays (0 when
 * it has none), compared with min_inlier_fraction. */
double matchInlierFraction(const plicp::MatchResult& m);

/** Squared Mahalanobis distance of e = predicted^-1 (+) measured (in the frame of
 * `predicted`, angle wrapped): e' S^-1 e, S = J measured_cov J' + drift_cov, where
 * J = diag(R(predicted.phi)', 1) carries the measurement's covariance (in the frame
 * of the older node) into e's frame. Infinity if S is not positive definite. */
double loopMahalanobis2(const mrpt::poses::CPose2D& predicted, const mrpt::poses::CPose2D& measured,
                        const Eigen::Matrix3d& measured_cov, const Eigen::Matrix3d& drift_cov);

/** Verifies one pair: PLICP of `newest`'s scan against `old`'s, starting from the graph's
 * relative vehicle pose carried into the sensor frame; then the overlap check and the gate on
 * the vehicle-frame result. Scans from different sensors give MatchFailed (InvalidInput).
 * With `search` (and search->enabled), a match that failed or overlaps too little is redone
 * from the best pose of a correlative search on the old scan around the guess, within
 * 3 drift standard deviations (capped by search->window_xy and window_theta): after a long
 * excursion the graph's guess is too far off for PLICP alone.
 * Throws std::invalid_argument for a missing node or scan, or old.id == newest.id. */
LoopCheck verifyLoop(const graph::PoseGraph& graph, const LoopNode& old, const LoopNode& newest,
                     const LoopClosureParams& p, const plicp::PlicpParams& plicp,
                     const std::optional<correlative::CorrelativeParams>& search = std::nullopt);

/** loopCandidates() (far candidates too when `path_length` is given) then verifyLoop() on
 * each; `node(id)` gives a candidate's LoopNode with its scan, asked for the candidates only.
 * Returns every check (for logs); the accepted ones carry an edge. */
std::vector<LoopCheck> checkLoops(const graph::PoseGraph& graph, const LoopNode& newest,
                                  const std::function<LoopNode(size_t)>& node,
                                  const std::function<double(size_t)>& path_length,
                                  const LoopClosureParams& p, const plicp::PlicpParams& plicp,
                                  const std::optional<correlative::CorrelativeParams>& search = std::nullopt);

}  // namespace swslam::loop
