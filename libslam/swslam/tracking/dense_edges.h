#pragma once
// A new node's edges (paper Fig. 2): the consecutive edge from tracking's match, and dense
// edges, each a PLICP match, to the recent nodes within dense_radius.

#include <swslam/graph/constraint.h>
#include <swslam/plicp/plicp.h>
#include <swslam/tracking/keyframe.h>
#include <swslam/tracking/params.h>
#include <swslam/tracking/prepared_scan.h>

#include <optional>
#include <vector>

namespace swslam::tracking
{
/** The consecutive edge of `node` from `match` (of its scan, in `previous`'s sensor frame),
 * with the match's covariance; without a match, priorEdge(). */
graph::Constraint consecutiveEdge(const Keyframe& previous, const Keyframe& node, const plicp::MatchResult& match,
                                  const TrackingParams& p);

/** An edge that only says "no match": the nodes' current relative pose, with the variance of
 * lost_prior_sigma_xy and lost_prior_sigma_theta (open water, a blind sensor). */
graph::Constraint priorEdge(const Keyframe& from, const Keyframe& to, const TrackingParams& p);

/** `node`'s scan matched by PLICP against `from`'s from their current relative pose: an edge
 * of `kind`, unless the match fails or lands farther than dense_gate_xy or dense_gate_theta
 * from that pose (another local minimum: low overlap, repeated structure, not a correction).
 * Along a direction the pair does not constrain, the chain decides (takePriorWhereWeak, with
 * lost_prior_sigma_xy): never a confident pull along a corridor. */
std::optional<graph::Constraint> matchEdge(const Keyframe& from, const Keyframe& node, const PreparedScan& scan,
                                           graph::EdgeKind kind, const TrackingParams& p,
                                           const plicp::PlicpParams& plicp);

struct DenseEdges
{
  std::vector<graph::Constraint> edges;
  size_t tried = 0;  ///< matches tried
};
/** The dense edges of the newest keyframe, `keyframes.back()` (its scan `scan`): matchEdge()
 * with the nearest max_dense_edges of the nodes before the previous one, among the last
 * dense_max_index_gap, within dense_radius. Older nodes within reach are loop candidates,
 * verified by the graph. */
DenseEdges denseEdges(const std::vector<Keyframe>& keyframes, const PreparedScan& scan, const TrackingParams& p,
                      const plicp::PlicpParams& plicp);

}  // namespace swslam::tracking
