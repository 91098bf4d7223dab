#include <swslam/graph/sliding_window.h>

#include <swslam/graph/initialization.h>

#include <limits>
#include <Eigen/Dense>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace swslam::graph
{
namespace
{
geometry::Pose2 toPose2(const mrpt::poses::CPose2D& p) { return geometry::Pose2(p.x(), p.y(), p.phi()); }

class SubproblemBuilder
{
 public:
  SubproblemBuilder(const PoseGraph& graph, const GraphOptimizerParams& params)
      : graph_(graph), params_(params)
  {
  }

  void reserve(size_t nodes, size_t edges)
  {
    index_.reserve(nodes);
    sub_.node_ids.reserve(nodes);
    sub_.problem.poses.reserve(nodes);
    sub_.problem.fixed.reserve(nodes);
    sub_.edge_indices.reserve(edges);
    sub_.problem.edges.reserve(edges);
  }

  int addNode(PoseGraph::TNodeID id, bool fixed)
  {
    const auto [it, inserted] = index_.emplace(id, static_cast<int>(sub_.node_ids.size()));
    if (inserted)
    {
      sub_.node_ids.push_back(id);
      sub_.problem.poses.push_back(toPose2(graph_.pose(id)));
      sub_.problem.fixed.push_back(fixed);
    }
    return it->second;
  }

  void addEdge(size_t index)
  {
    const PoseGraph::Edge& e = graph_.edge(index);
    sub_.edge_indices.push_back(index);
    GraphProblem::Edge pe;
    pe.i = addNode(e.from, true);
    pe.j = addNode(e.to, true);
    pe.z = toPose2(e.measurement->mean);
    pe.information = e.measurement->cov_inv.asEigen();
    pe.robust = params_.isRobust(e.kind);
    pe.kind = e.kind;
    sub_.problem.edges.push_back(pe);
  }

  /** Problem index of node `id`, or INT_MAX if not in the problem (yet). */
  int indexOf(PoseGraph::TNodeID id) const
  {
    const auto it = index_.find(id);
    return it == index_.end() ? std::numeric_limits<int>::max() : it->second;
  }
  GraphSubproblem& result() { return sub_; }

 private:
  const PoseGraph& graph_;
  const GraphOptimizerParams& params_;
  GraphSubproblem sub_;
  std::unordered_map<PoseGraph::TNodeID, int> index_;
};
}  // namespace

GraphSubproblem windowSubproblem(const PoseGraph& graph, size_t window_size,
                                 const GraphOptimizerParams& params)
{
  if (graph.nodeCount() == 0) throw std::invalid_argument("window: the graph has no nodes");
  if (window_size == 0) throw std::invalid_argument("window: window_size is 0");
  std::vector<PoseGraph::TNodeID> window = graph.newestNodes(window_size);
  window.erase(std::remove_if(window.begin(), window.end(), [&](auto id) { return graph.isMerged(id); }),
               window.end());
  SubproblemBuilder builder(graph, params);
  for (const auto id : window) builder.addNode(id, false);
  const size_t window_count = window.size();
  if (window_count == 0) return std::move(builder.result());  // every newest node merged: nothing free
  // Each edge once: from the window node at its `from` end, or at its `to` end when the
  // `from` node lies outside the window.
  for (const auto id : window)
    for (const size_t k : graph.edgesOf(id))
    {
      const PoseGraph::Edge& e = graph.edge(k);
      const bool from_in_window = builder.indexOf(e.from) < static_cast<int>(window_count);
      if (e.from == id || !from_in_window)
        builder.addEdge(k);
    }
  GraphSubproblem& sub = builder.result();
  if (sub.node_ids.size() == window_count)
  {
    // Nothing outside anchors the window: hold a gauge node fixed.
    int gauge = 0;
    for (size_t n = 0; n < window_count; ++n)
      if (sub.node_ids[n] == graph.root()) gauge = static_cast<int>(n);
    sub.problem.fixed[gauge] = 1;
  }
  return std::move(sub);
}

GraphSubproblem fullSubproblem(const PoseGraph& graph, const GraphOptimizerParams& params)
{
  if (graph.nodeCount() == 0) throw std::invalid_argument("full optimization: empty graph");
  SubproblemBuilder builder(graph, params);
  builder.reserve(graph.liveNodeCount(), graph.edgeCount());
  for (const auto id : graph.nodeIds())
    if (!graph.isMerged(id)) builder.addNode(id, id == graph.root());
  for (size_t k = 0; k < graph.edgeCount(); ++k) builder.addEdge(k);
  return std::move(builder.result());
}

void writeBack(const GraphSubproblem& sub, PoseGraph& graph)
{
  for (size_t n = 0; n < sub.node_ids.size(); ++n)
  {
    if (sub.problem.fixed[n]) continue;
    const geometry::Pose2& p = sub.problem.poses[n];
    graph.setPose(sub.node_ids[n], mrpt::poses::CPose2D(p.x(), p.y(), p.z()));
    graph.placeMergedInto(sub.node_ids[n]);
  }
}

namespace
{
OptimizationReport optimizeSubproblem(GraphSubproblem sub, PoseGraph& graph,
                                      const GraphOptimizerParams& params, bool whole = false)
{
  OptimizationReport rep = whole ? optimizeFromBestStart(sub.problem, params) : optimizeGraphProblem(sub.problem, params);
  if (rep.status != OptimizationStatus::Diverged) writeBack(sub, graph);
  for (size_t& k : rep.switched_off) k = sub.edge_indices[k];  // the graph's edge indices
  return rep;
}
}  // namespace

OptimizationReport optimizeWindow(PoseGraph& graph, const GraphOptimizerParams& params)
{
  return optimizeSubproblem(windowSubproblem(graph, params.window_size, params), graph, params);
}

OptimizationReport optimizeFull(PoseGraph& graph, const GraphOptimizerParams& params)
{
  return optimizeSubproblem(fullSubproblem(graph, params), graph, params, /*whole=*/true);
}

}  // namespace swslam::graph
