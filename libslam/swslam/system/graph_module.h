#pragma once
// The graph optimization module (paper Fig. 1, sec. III): adds each new node with its edges,
// optimizes the sliding window, looks for loops (index gap + distance), verifies them by
// PLICP and a chi-square gate, and on an accepted loop that corrects the graph optimizes the
// whole graph (at most once per [graph_optimizer] full_optimization_interval nodes while
// loops keep coming). On revisits, a node a loop ties to an earlier node, where the area holds
// max_nodes_per_area earlier nodes already, is merged into it (PoseGraph::merge): the graph
// and the map grow with the area mapped, not with the path.
//
// Threading: one thread (the graph thread, or the deterministic loop) calls addNode() and
// optimizeAll() and refineAll(); graphCopy() and the counters may be called from any thread.

#include <swslam/graph/optimizer.h>
#include <swslam/graph/optimizer_params.h>
#include <swslam/graph/pose_graph.h>
#include <swslam/loop/closer.h>
#include <swslam/loop/corroboration.h>
#include <swslam/loop/final_refinement_params.h>
#include <swslam/plicp/reference_store.h>
#include <swslam/system/full_optimization_schedule.h>
#include <swslam/system/messages.h>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <tuple>
#include <vector>

namespace swslam::system
{
/** Edges told apart by their nodes and kind (edges fused into one keep them). */
using EdgeSignature = std::tuple<graph::PoseGraph::TNodeID, graph::PoseGraph::TNodeID, int>;

/** What one graph step did, and what the other modules must learn from it. */
struct GraphStep
{
  size_t scan = 0;
  size_t node = 0;
  size_t loops_checked = 0, loops_accepted = 0;
  size_t pairs_refined = 0, refinement_edges = 0;  ///< final refinement: pairs matched, edges added
  size_t edges_rejected = 0;  ///< tracker edges the graph refused (e.g. non-finite)
  bool full = false;          ///< the whole graph was optimized
  /** The earlier pass's node that the node leaving the window was merged into (its scan then
   * leaves the map: reinsert.removed). */
  std::optional<size_t> merged_into;
  graph::OptimizationReport report;
  PoseUpdate poses;                ///< optimized node poses (for tracking)
  std::optional<MapInsert> insert;  ///< for the map: the new node's scan, at its optimized pose...
  MapReinsert reinsert;             ///< ...then the optimized poses (moved nodes are re-inserted)
};

class GraphModule
{
 public:
  /** `search`: the correlative search of loop checks whose match from the graph's guess
   * failed (verifyLoop); none when not given. */
  GraphModule(const graph::GraphOptimizerParams& graph, const loop::LoopClosureParams& loops,
              const plicp::PlicpParams& plicp, const std::optional<correlative::CorrelativeParams>& search = std::nullopt);

  /** Adds the node (its pose re-based on the graph's estimate of the previous node), its
   * edges and any verified loop, then optimizes the window, or everything after a loop that
   * corrects the graph (FullOptimizationSchedule, loopCorrectsGraph). */
  GraphStep addNode(const NewNode& node);

  /** Continues a saved session (before the first node): `graph` with nodes 0..n-1 and
   * `scans[id]` each node's scan (null for a node merged into another: not matched again). A node's path length is summed over the consecutive edges
   * (k-1 -> k) as addNode sums it. Throws std::logic_error after a node, std::invalid_argument
   * for a graph whose nodes are not 0..n-1 or a scan count that differs. */
  void restore(graph::PoseGraph graph, const std::vector<std::shared_ptr<const plicp::ReferenceScan>>& scans);

  /** Optimizes the whole graph (e.g. at the end of a run). */
  GraphStep optimizeAll(size_t scan);

  /** The final refinement (loop/final_refinement.h), `p.passes` rounds: matches every close
   * pair of nodes that shares no edge, adds the accepted matches as loop edges and, if any,
   * optimizes the whole graph. A round that adds no edge ends the pass early. The step's poses
   * are those of the last optimization (none when no edge was added). */
  GraphStep refineAll(size_t scan, const loop::FinalRefinementParams& p);

  graph::PoseGraph graphCopy() const;
  size_t loopCount() const;

 private:
  void addEdge(const graph::Constraint& e, GraphStep& step);
  /** Checks node `id`'s loop candidates and adds the corroborated loops (counted in
   * step.loops_accepted); returns how many of them disagree with the graph enough to ask
   * for a full optimization (loopCorrectsGraph). */
  size_t closeLoops(size_t id, GraphStep& step, std::vector<graph::Constraint>& accepted);
  /** Of the loops accepted at node `id`, the one that ties it to the earlier pass's node it is
   * to be merged into ([graph_optimizer] max_nodes_per_area), agreeing with the graph now; none
   * to keep it. The node is then held at its pose relative to that node, with the loop's
   * information. */
  std::optional<graph::Constraint> redundantWith(size_t id, const std::vector<graph::Constraint>& loops) const;
  /** Node `id`, leaving the sliding window, merged into an earlier pass's node if redundantWith
   * its loops says so: held there, its scan released and removed from the map (step.reinsert). */
  void mergeIfRedundant(size_t id, GraphStep& step);
  void optimize(bool full, GraphStep& step);
  /** Node `n` for loop closure, with its scan (rebuilt by the store if not kept). */
  loop::LoopNode loopNode(size_t n) const;

  const graph::GraphOptimizerParams graph_params_;
  const loop::LoopClosureParams loop_params_;
  const plicp::PlicpParams plicp_params_;
  const std::optional<correlative::CorrelativeParams> search_params_;
  std::vector<loop::LoopNode> nodes_;  ///< by node id, without scans (in scans_); only the owning thread
  plicp::ReferenceStore scans_;        ///< the nodes' scans
  mutable std::mutex mutex_;
  graph::PoseGraph graph_;    ///< guarded by mutex_ for readers; written by the owning thread
  size_t loops_ = 0;   ///< guarded by mutex_
  FullOptimizationSchedule schedule_;  ///< only the owning thread
  loop::LoopCorroboration corroboration_;    ///< only the owning thread
  /** The edges the last full optimization switched off; only the owning thread. */
  std::set<EdgeSignature> switched_off_;
  /** A full optimization switched an edge off anew: GNC takes a second look at the next step
   * that optimizes only the window (or at the end of the run). Only the owning thread. */
  bool second_look_due_ = false;
  /** The loops accepted at each node still in the sliding window (max_nodes_per_area > 0): its
   * merge is decided as it leaves the window. Only the owning thread. */
  std::map<size_t, std::vector<graph::Constraint>> loops_of_window_;
};

}  // namespace swslam::system
