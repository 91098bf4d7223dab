#include "swslam/system/graph_module.h"

#include "swslam/sliding_window.h"

#include <mrpt/system/CTimeLogger.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam
{
using mrpt::poses::CPose2D;

GraphModule::GraphModule(const GraphOptimizerParams& graph, const LoopClosureParams& loops,
                         const PlicpParams& plicp, const std::optional<CorrelativeParams>& search)
    : graph_params_(graph),
      loop_params_(loops),
      plicp_params_(plicp),
      search_params_(search),
      schedule_(graph.full_optimization_interval)
{
}

void GraphModule::addEdge(const TrackerEdge& e, GraphStep& step)
{
  mrpt::poses::CPosePDFGaussianInf z;
  z.mean = e.z;
  z.cov_inv = mrpt::math::CMatrixDouble33(e.information);
  try
  {
    graph_.addEdge(e.from, e.to, z, e.kind);
  }
  catch (const std::invalid_argument&)
  {
    step.edges_rejected++;
  }
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
    for (const TrackerEdge& e : node.edges) addEdge(e, step);
  }
  LoopNode ln;
  ln.id = id;
  ln.scan = node.keyframe.scan;
  ln.path_length = 0;
  if (!nodes_.empty())
  {
    const LoopNode& prev = nodes_.back();
    ln.path_length = prev.path_length + node.edges.front().z.norm();
  }
  nodes_.push_back(ln);

  step.loops_accepted = closeLoops(id, step);
  optimize(schedule_.fullNow(id, step.loops_accepted), step);
  step.insert = MapInsert{node.scan, id, node.observation,
                          step.poses.count(id) ? step.poses.at(id) : graph_.pose(id)};
  return step;
}

size_t GraphModule::closeLoops(size_t id, GraphStep& step)
{
  if (!loop_params_.enabled) return 0;
  size_t accepted = 0;
  const auto checks = checkLoops(
      graph_, nodes_.at(id), [this](size_t n) { return nodes_.at(n); }, loop_params_, plicp_params_,
      search_params_);
  std::vector<TrackerEdge> verified;
  for (const LoopCheck& check : checks)
  {
    step.loops_checked++;
    if (check.edge) verified.push_back(*check.edge);
  }
  for (const TrackerEdge& e : corroborated(id, verified))
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const size_t before = step.edges_rejected;
    addEdge(e, step);
    if (step.edges_rejected == before)
    {
      accepted++;
      loops_++;
    }
  }
  return accepted;
}

std::vector<TrackerEdge> GraphModule::corroborated(size_t id, const std::vector<TrackerEdge>& verified)
{
  const auto w = static_cast<size_t>(loop_params_.consistency_window);
  if (w == 0) return verified;
  pending_.erase(std::remove_if(pending_.begin(), pending_.end(),
                                [&](const PendingLoop& p) { return p.edge.to + w < id; }),
                 pending_.end());
  auto near = [w](size_t a, size_t b) { return (a > b ? a - b : b - a) <= w; };
  std::vector<TrackerEdge> out;
  for (const TrackerEdge& e : verified)
  {
    PendingLoop v;
    v.edge = e;
    v.measure = LoopEdgeMeasure{e.from, e.to, e.z, e.information.inverse()};
    for (PendingLoop& p : pending_)
    {
      if (!near(p.edge.from, e.from) || !near(p.edge.to, e.to)) continue;
      const LoopEdgeMeasure& l1 = p.measure;  // a -> n
      const CPose2D rel_ab = graph_.pose(e.from) - graph_.pose(l1.from);
      const CPose2D rel_nm = graph_.pose(e.to) - graph_.pose(l1.to);
      const double path = std::abs(nodes_.at(e.from).path_length - nodes_.at(l1.from).path_length) +
                          std::abs(nodes_.at(e.to).path_length - nodes_.at(l1.to).path_length);
      const Eigen::Matrix3d local = driftCovariance(path, loop_params_);
      if (!(loopPairChi2(l1, v.measure, rel_ab, rel_nm, std::sqrt(local(0, 0)), std::sqrt(local(2, 2))) <=
            loop_params_.chi2_gate))
        continue;
      if (!p.added) out.push_back(p.edge);
      p.added = true;
      v.added = true;
    }
    if (v.added) out.push_back(e);
    pending_.push_back(v);
  }
  return out;
}

void GraphModule::optimize(bool full, GraphStep& step)
{
  step.full = full;
  std::lock_guard<std::mutex> lock(mutex_);
  step.report = full ? optimizeFull(graph_, graph_params_) : optimizeWindow(graph_, graph_params_);
  const std::vector<PoseGraph::TNodeID> ids =
      full ? graph_.nodeIds() : graph_.newestNodes(graph_params_.window_size);
  step.reinsert.scan = step.scan;
  for (const auto id : ids)
  {
    step.poses[id] = graph_.pose(id);
    step.reinsert.poses[id] = graph_.pose(id);
  }
}

GraphStep GraphModule::optimizeAll(size_t scan)
{
  GraphStep step;
  step.scan = scan;
  if (nodes_.empty()) return step;
  schedule_.ranFull(nodes_.size() - 1);
  optimize(true, step);
  return step;
}

PoseGraph GraphModule::graphCopy() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return graph_;
}

size_t GraphModule::loopCount() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return loops_;
}

}  // namespace swslam
