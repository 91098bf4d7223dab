#pragma once
// Final refinement (doc/loop-closure.md): once the input ends and the whole graph is
// optimized, every pair of nodes that are close at their optimized poses but share no edge
// (whatever their id gap: dense edges only reach the last [tracking] dense_max_index_gap
// nodes, and loop closure checks a few candidates per node) is matched by PLICP from the
// graph's relative pose. A match is accepted as loop closure accepts one (verifyLoop: it
// converges, overlaps enough, passes the chi-square gate), with the drift model replaced by a
// fixed error of the optimized graph, and only if it stays within a gate of the guess. The
// caller adds the accepted edges (kind Loop) and optimizes the whole graph again.
// Pure functions: no threads, no config reading.

#include <swslam/graph/pose_graph.h>
#include <swslam/loop/closer.h>
#include <swslam/loop/final_refinement_params.h>
#include <swslam/plicp/plicp.h>

#include <functional>
#include <utility>
#include <vector>

namespace swslam::loop
{
/** Every pair (i, j), i < j, of graph nodes at most `radius` apart (vehicle positions) that
 * share no edge, in increasing (i, j) order; with max_per_node > 0, only the max_per_node
 * nearest partners of each newer node j (a run that circles the same place many times keeps a
 * bounded number of matches per node). O(n^2) distances, no scan work. */
std::vector<std::pair<size_t, size_t>> unlinkedClosePairs(const graph::PoseGraph& graph, double radius,
                                                          size_t max_per_node = 0);

/** verifyLoop() of the pair's newer node against the older one with the acceptance of `p`
 * (no correlative search: the optimized graph's guess is close); an accepted match that moves
 * the guess more than max_correction_xy or turns it more than max_correction_theta becomes
 * GateRejected, without an edge. Throws as verifyLoop(). */
LoopCheck verifyRefinementPair(const graph::PoseGraph& graph, const LoopNode& older, const LoopNode& newer,
                               const FinalRefinementParams& p, const plicp::PlicpParams& plicp);

/** What one pass of the refinement found: how many pairs it matched and the edges accepted. */
struct RefinementEdges
{
  size_t pairs = 0;
  std::vector<graph::Constraint> edges;  ///< kind Loop, older -> newer, in pair order
};

/** unlinkedClosePairs() then verifyRefinementPair() on each; `node(id)` gives a LoopNode.
 * Keeps only the accepted edges (a long run matches tens of thousands of pairs). */
RefinementEdges refinementEdges(const graph::PoseGraph& graph, const std::function<LoopNode(size_t)>& node,
                                const FinalRefinementParams& p, const plicp::PlicpParams& plicp);

}  // namespace swslam::loop
