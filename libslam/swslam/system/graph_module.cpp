#include <swslam/system/graph_module.h>

#include <swslam/graph/sliding_window.h>
#include <swslam/loop/final_refinement.h>

#include <mrpt/system/CTimeLogger.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace swslam::system
{
using mrpt::poses::CPose2D;

GraphModule::GraphModule(const graph::GraphOptimizerParams& graph, const loop::LoopClosureParams& loops,
                         const plicp::PlicpParams& plicp, const std::optional<correlative::CorrelativeParams>& search)
    : graph_params_(graph),
      loop_params_(loops),
      plicp_params_(plicp),
      search_params_(search),
      scans_(plicp),
      schedule_(graph.full_optimization_interval),
      corroboration_(loops)
{
}

void GraphModule::addEdge(const graph::Constraint& e, GraphStep& step)
{
  mrpt::poses::CPosePDFGaussianInf z;
  z.mean = e.z;
  z.cov_inv = mrpt::math::CMatrixDouble33(e.information);
  try
  {
    graph_.addEdge(e.from, e.to, z, e.kind);  // an edge a merge folds into one node is not kept
  }
  catch (const std::invalid_argument&)
  {
    step.edges_rejected++;
  }
}

void GraphModule::restore(graph::PoseGraph graph, const std::vector<std::shared_ptr<const plicp::ReferenceScan>>& scans)
{
  if (!nodes_.empty()) throw std::logic_error("graph: a session is restored before the first node");
  const size_t n = graph.nodeCount();
  if (n == 0 || scans.size() != n)
    throw std::invalid_argument("graph: a restored session needs one scan per node (" + std::to_string(scans.size()) +
                                " for " + std::to_string(n) + " nodes)");
  std::vector<double> step(n, 0.0);  // the consecutive edge's length into each node
  size_t loops = 0;
  for (size_t k = 0; k < graph.edgeCount(); k++)
  {
    const auto& e = graph.edge(k);
    if (e.kind == graph::EdgeKind::Loop) loops++;
    if (e.kind == graph::EdgeKind::Consecutive && e.to == e.from + 1 && e.to < n) step[e.to] = e.measurement->mean.norm();
  }
  for (size_t id = 0; id < n; id++)
  {
    if (!graph.hasNode(id))
      throw std::invalid_argument("graph: a restored session's nodes must be 0.." + std::to_string(n - 1) + "; " +
                                  std::to_string(id) + " is missing");
    if (graph.isMerged(id)) scans_.addReleased(id);
    else scans_.add(id, scans[id]);
    loop::LoopNode ln;
    ln.id = id;
    ln.path_length = id == 0 ? 0.0 : nodes_.back().path_length + step[id];
    nodes_.push_back(ln);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  graph_ = std::move(graph);
  loops_ = loops;
}

GraphStep GraphModule::addNode(const NewNode& node)
{
  GraphStep step;
  step.scan = node.scan;
  step.node = node.keyframe.id;
  const size_t id = node.keyframe.id;
  if (id != nodes_.size())
    throw std::logic_error("graph: node " + std::to_string(id) + " arrived out of order");
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // The tracker placed the node relative to its copy of the previous node; the graph's
    // estimate of that node may have moved since.
    CPose2D pose = node.keyframe.pose;
    if (!node.edges.empty() && graph_.hasNode(node.edges.front().from))
      pose = graph_.pose(node.edges.front().from) + node.edges.front().z;
    graph_.addNode(id, pose);
    for (const graph::Constraint& e : node.edges) addEdge(e, step);
  }
  if (!node.keyframe.scan)
    throw std::logic_error("graph: node " + std::to_string(id) + " arrived without its scan");
  scans_.add(id, node.keyframe.scan);
  loop::LoopNode ln;
  ln.id = id;
  ln.path_length = 0;
  if (!nodes_.empty())
  {
    const loop::LoopNode& prev = nodes_.back();
    ln.path_length = prev.path_length + node.edges.front().z.norm();
  }
  nodes_.push_back(ln);

  std::vector<graph::Constraint> loops;
  const size_t correcting = closeLoops(id, step, loops);
  optimize(schedule_.fullNow(id, correcting), step);
  step.insert = MapInsert{node.scan, id, node.observation,
                          step.poses.count(id) ? step.poses.at(id) : graph_.pose(id)};
  if (!loops.empty() && graph_params_.max_nodes_per_area > 0) loops_of_window_.emplace(id, std::move(loops));
  if (id >= graph_params_.window_size) mergeIfRedundant(id - graph_params_.window_size, step);
  return step;
}

void GraphModule::mergeIfRedundant(size_t id, GraphStep& step)
{
  const auto it = loops_of_window_.find(id);
  if (it == loops_of_window_.end()) return;
  const std::vector<graph::Constraint> loops = std::move(it->second);
  loops_of_window_.erase(it);
  const auto tie = redundantWith(id, loops);
  if (!tie) return;
  // Held where the optimizations put it (the loop with the rest of the graph: the loop alone
  // would carry its own match error into every later edge), as certain as the loop.
  mrpt::poses::CPosePDFGaussianInf z;
  z.mean = graph_.pose(id) - graph_.pose(tie->from);
  z.cov_inv = mrpt::math::CMatrixDouble33(tie->information);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    graph_.merge(id, tie->from, z);
    step.poses[id] = graph_.pose(id);
  }
  step.reinsert.poses.erase(id);
  step.reinsert.removed.push_back(id);  // its scan leaves the map
  scans_.release(id);
  step.merged_into = tie->from;
}

std::optional<graph::Constraint> GraphModule::redundantWith(size_t id, const std::vector<graph::Constraint>& loops) const
{
  const size_t bound = graph_params_.max_nodes_per_area;
  const double radius = graph_params_.node_area_radius;
  if (bound == 0 || graph_.isMerged(id) || graph_.isAnchor(id)) return std::nullopt;
  // The loop into `id` from the nearest earlier node that holds a scan and agrees with the graph.
  const CPose2D& here = graph_.pose(id);
  std::optional<graph::Constraint> tie;
  double nearest = radius;
  for (const graph::Constraint& e : loops)
  {
    if (e.to != id || graph_.isMerged(e.from)) continue;
    const CPose2D relative = here - graph_.pose(e.from);
    const double d = relative.norm();
    if (d > nearest || loopCorrectsGraph(relative, e.z, graph_params_.full_optimization_loop_xy,
                                         graph_params_.full_optimization_loop_theta))
      continue;
    nearest = d;
    tie = e;
  }
  if (!tie) return std::nullopt;
  // The earlier passes' nodes in the area (the recent ones are this pass's own).
  const auto gap = static_cast<size_t>(loop_params_.min_index_gap);
  size_t earlier = 0;
  for (const auto& [n, pose] : graph_.network().nodes)
  {
    if (n + gap > id) break;
    earlier += !graph_.isMerged(n) && (pose.translation() - here.translation()).norm() <= radius;
  }
  if (earlier < bound) return std::nullopt;
  return tie;
}

size_t GraphModule::closeLoops(size_t id, GraphStep& step, std::vector<graph::Constraint>& accepted)
{
  if (!loop_params_.enabled) return 0;
  size_t correcting = 0;
  const auto path_length = [this](size_t n) { return nodes_.at(n).path_length; };
  const auto checks = loop::checkLoops(
      graph_, loopNode(id), [this](size_t n) { return loopNode(n); }, path_length, loop_params_, plicp_params_,
      search_params_);
  std::vector<graph::Constraint> verified;
  for (const loop::LoopCheck& check : checks)
  {
    step.loops_checked++;
    if (check.edge) verified.push_back(*check.edge);
  }
  const auto corroborated = corroboration_.add(
      id, verified, [this](size_t n) { return graph_.pose(n); }, path_length);
  for (const graph::Constraint& e : corroborated)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool corrects =
        graph_.hasNode(e.from) && graph_.hasNode(e.to) &&
        loopCorrectsGraph(graph_.pose(e.to) - graph_.pose(e.from), e.z,
                          graph_params_.full_optimization_loop_xy,
                          graph_params_.full_optimization_loop_theta);
    const size_t before = step.edges_rejected;
    addEdge(e, step);
    if (step.edges_rejected == before)
    {
      step.loops_accepted++;
      correcting += corrects;
      loops_++;
      accepted.push_back(e);
    }
  }
  return correcting;
}

namespace
{
/** Whether graph edge `k` measures a step of the chain again: a consecutive or dense-neighbour
 * edge joins the same two nodes. */
bool repeatsAChainStep(const graph::PoseGraph& graph, size_t k)
{
  const graph::PoseGraph::Edge& e = graph.edge(k);
  for (const size_t other : graph.edgesOf(e.from))
  {
    const graph::PoseGraph::Edge& o = graph.edge(other);
    const bool chain = o.kind == graph::EdgeKind::Consecutive || o.kind == graph::EdgeKind::DenseNeighbour;
    if (other != k && chain && (o.from == e.to || o.to == e.to)) return true;
  }
  return false;
}

/** The switched-off edges of a report (graph edge indices) that may ask for a second look: by
 * their nodes and kind (a fused edge keeps them), those that repeat a chain step left out. Such
 * an edge is weighed against the other measurements of that step alike from any start. */
std::set<EdgeSignature> signatures(const graph::PoseGraph& graph, const std::vector<size_t>& switched_off)
{
  std::set<EdgeSignature> out;
  for (const size_t k : switched_off)
  {
    const graph::PoseGraph::Edge& e = graph.edge(k);
    if (!repeatsAChainStep(graph, k)) out.emplace(e.from, e.to, static_cast<int>(e.kind));
  }
  return out;
}

/** The whole graph with the fixed kernel (optimizeFull: from the graph's poses or LAGO's);
 * `anew` tells whether it switched off an edge it had not switched off at the last full
 * optimization (`off`, updated). Started at the chain's guess, the fixed kernel gives no weight
 * to loops that disagree with the chain by far, right or wrong: a wrong consecutive edge keeps
 * the chain and the true loops are switched off. Such a result gets a second look (secondLook).
 * An edge the fixed kernel switches off again has had it, whichever result was kept. */
graph::OptimizationReport optimizeFixed(graph::PoseGraph& graph, const graph::GraphOptimizerParams& params,
                                        std::set<EdgeSignature>& off, bool& anew)
{
  graph::OptimizationReport report = graph::optimizeFull(graph, params);
  std::set<EdgeSignature> fixed_off = signatures(graph, report.switched_off);
  anew = std::any_of(fixed_off.begin(), fixed_off.end(), [&](const auto& e) { return off.count(e) == 0; });
  off = std::move(fixed_off);
  return report;
}

/** Graduated non-convexity on the whole graph from its poses, kept if it costs less under the
 * fixed kernel than the graph as it is (the cost both minimize): GNC weighs every edge again from
 * a convex stage (doc/graph-optimization.md). Its final least-squares solve costs a little more
 * under the kernel when both switch the same edges off, so then the graph stays. None if it
 * stays. */
std::optional<graph::OptimizationReport> secondLook(graph::PoseGraph& graph, const graph::GraphOptimizerParams& params)
{
  graph::GraphSubproblem sub = graph::fullSubproblem(graph, params);
  graph::GraphProblem second = sub.problem;
  graph::GraphOptimizerParams gnc = params;
  gnc.kernel_schedule = graph::KernelSchedule::Gnc;
  graph::OptimizationReport report = graph::optimizeGraphProblem(second, gnc);
  const auto kernels = graph::uniformKernels(params.kernel());
  if (report.status == graph::OptimizationStatus::Diverged ||
      !(graph::robustCost(second, kernels) < graph::robustCost(sub.problem, kernels)))
    return std::nullopt;
  sub.problem.poses = std::move(second.poses);
  graph::writeBack(sub, graph);
  for (size_t& k : report.switched_off) k = sub.edge_indices[k];
  return report;
}
}  // namespace

loop::LoopNode GraphModule::loopNode(size_t n) const
{
  loop::LoopNode ln = nodes_.at(n);
  ln.scan = scans_.get(n);
  return ln;
}

void GraphModule::optimize(bool full, GraphStep& step)
{
  std::lock_guard<std::mutex> lock(mutex_);
  // A second look is taken at the next step that optimizes only the window, so that no step
  // runs both whole-graph solves.
  std::optional<graph::OptimizationReport> looked;
  if (!full && second_look_due_)
  {
    second_look_due_ = false;
    looked = secondLook(graph_, graph_params_);
  }
  bool anew = false;
  if (looked) step.report = std::move(*looked);
  else if (!full) step.report = graph::optimizeWindow(graph_, graph_params_);
  else if (graph_params_.kernel_schedule != graph::KernelSchedule::Fixed)
    step.report = graph::optimizeFull(graph_, graph_params_);
  else
    step.report = optimizeFixed(graph_, graph_params_, switched_off_, anew);
  second_look_due_ = second_look_due_ || anew;
  full = full || looked;
  step.full = step.full || full;
  const std::vector<graph::PoseGraph::TNodeID> ids =
      full ? graph_.nodeIds() : graph_.newestNodes(graph_params_.window_size);
  step.reinsert.scan = step.scan;
  // The ids ascend: each new entry goes at the end of the maps (a hint, not a search).
  for (const auto id : ids)
  {
    const CPose2D& pose = graph_.pose(id);
    step.poses.insert_or_assign(step.poses.end(), id, pose);
    if (!graph_.isMerged(id)) step.reinsert.poses.insert_or_assign(step.reinsert.poses.end(), id, pose);  // a merged node is not mapped
  }
}

GraphStep GraphModule::optimizeAll(size_t scan)
{
  GraphStep step;
  step.scan = scan;
  if (nodes_.empty()) return step;
  schedule_.ranFull(nodes_.size() - 1);
  optimize(true, step);
  if (second_look_due_) optimize(false, step);  // the run ends: now
  return step;
}

GraphStep GraphModule::refineAll(size_t scan, const loop::FinalRefinementParams& p)
{
  GraphStep step;
  step.scan = scan;
  if (!p.enabled || nodes_.empty()) return step;
  for (int pass = 0; pass < p.passes; ++pass)
  {
    const auto found = loop::refinementEdges(
        graph_, [this](size_t n) { return loopNode(n); }, p, plicp_params_);
    size_t added = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const graph::Constraint& edge : found.edges)
      {
        const size_t before = step.edges_rejected;
        addEdge(edge, step);
        added += step.edges_rejected == before;
      }
    }
    step.pairs_refined += found.pairs;
    step.refinement_edges += added;
    if (added == 0) break;
    schedule_.ranFull(nodes_.size() - 1);
    optimize(true, step);
  }
  if (second_look_due_) optimize(false, step);  // the run ends: now
  return step;
}

graph::PoseGraph GraphModule::graphCopy() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return graph_;
}

size_t GraphModule::loopCount() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return loops_;
}

}  // namespace swslam::system
