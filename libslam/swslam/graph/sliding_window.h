#pragma once
// Pose-graph optimization on a PoseGraph: the sliding window of the newest nodes (paper
// section III-B, run whenever a node is added) and the whole graph (run on loop closure).
//
// Window: the newest N nodes are free; every node outside the window that shares an edge
// with it is held fixed and its edges still constrain the window. The window's edges are
// found through the per-node adjacency, so an update costs O(N * degree * log(total)) —
// independent of the size of the graph up to the map look-up.

#include <swslam/graph/optimizer.h>
#include <swslam/graph/pose_graph.h>

#include <vector>

namespace swslam::graph
{
/** A GraphProblem cut from a PoseGraph, with the node id of each problem pose. */
struct GraphSubproblem
{
  GraphProblem problem;
  std::vector<PoseGraph::TNodeID> node_ids;  ///< parallel to problem.poses
  std::vector<size_t> edge_indices;          ///< graph edge index, parallel to problem.edges
};

/** The newest `window_size` nodes free (those merged into others left out: they are not
 * optimized), their outside neighbours fixed. If nothing outside
 * anchors the window (the window holds the whole connected graph), the graph's root is
 * fixed if it is in the window, otherwise the oldest window node. Throws
 * std::invalid_argument for an empty graph or window_size == 0. */
GraphSubproblem windowSubproblem(const PoseGraph& graph, size_t window_size,
                                 const GraphOptimizerParams& params);

/** Every node free except the root (gauge) and the merged ones. Throws std::invalid_argument
 * if empty. */
GraphSubproblem fullSubproblem(const PoseGraph& graph, const GraphOptimizerParams& params);

/** Copies the free poses of `sub` back into `graph`, with the nodes merged into them. */
void writeBack(const GraphSubproblem& sub, PoseGraph& graph);

/** Optimizes the sliding window of params.window_size newest nodes; the graph is updated
 * unless the report says Diverged. The report's switched_off are the graph's edge indices
 * (also for optimizeFull). */
OptimizationReport optimizeWindow(PoseGraph& graph, const GraphOptimizerParams& params);

/** Optimizes the whole graph with the root fixed, from its poses or, where they are a poor
 * guess, from LAGO's (optimizeFromBestStart); updated unless Diverged. */
OptimizationReport optimizeFull(PoseGraph& graph, const GraphOptimizerParams& params);

}  // namespace swslam::graph
