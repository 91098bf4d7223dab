#include <swslam/loop/final_refinement.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace swslam::loop
{
using mrpt::poses::CPose2D;

std::vector<std::pair<size_t, size_t>> unlinkedClosePairs(const graph::PoseGraph& graph, double radius,
                                                          size_t max_per_node)
{
  std::vector<std::pair<size_t, size_t>> pairs;
  std::vector<double> dist;  // of each pair
  auto ids = graph.nodeIds();  // the merged ones hold no scan of their own
  ids.erase(std::remove_if(ids.begin(), ids.end(), [&](size_t id) { return graph.isMerged(id); }), ids.end());
  std::vector<size_t> linked;  // the other ends of node i's edges
  for (size_t a = 0; a < ids.size(); ++a)
  {
    const size_t i = ids[a];
    linked.clear();
    for (const size_t e : graph.edgesOf(i))
    {
      const auto& edge = graph.edge(e);
      linked.push_back(edge.from == i ? edge.to : edge.from);
    }
    std::sort(linked.begin(), linked.end());
    const auto here = graph.pose(i).translation();
    for (size_t b = a + 1; b < ids.size(); ++b)
    {
      const size_t j = ids[b];
      const double d = (graph.pose(j).translation() - here).norm();
      if (d <= radius && !std::binary_search(linked.begin(), linked.end(), j))
      {
        pairs.emplace_back(i, j);
        dist.push_back(d);
      }
    }
  }
  if (max_per_node == 0) return pairs;
  // Each newer node keeps its nearest max_per_node partners (ties: the older one first).
  std::vector<size_t> order(pairs.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::tie(pairs[a].second, dist[a], pairs[a].first) <
           std::tie(pairs[b].second, dist[b], pairs[b].first);
  });
  std::vector<std::pair<size_t, size_t>> kept;
  for (size_t k = 0, run = 0; k < order.size(); ++k)
  {
    run = k > 0 && pairs[order[k]].second == pairs[order[k - 1]].second ? run + 1 : 0;
    if (run < max_per_node) kept.push_back(pairs[order[k]]);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

LoopCheck verifyRefinementPair(const graph::PoseGraph& graph, const LoopNode& older, const LoopNode& newer,
                               const FinalRefinementParams& p, const plicp::PlicpParams& plicp)
{
  // The loop check's acceptance with a drift that does not grow with the path: its floors.
  LoopClosureParams accept;
  accept.min_inlier_fraction = p.min_inlier_fraction;
  accept.chi2_gate = p.chi2_gate;
  accept.drift_xy_per_m = 0;
  accept.drift_theta_per_m = 0;
  accept.min_drift_sigma_xy = p.sigma_xy;
  accept.min_drift_sigma_theta = p.sigma_theta;
  LoopCheck c = verifyLoop(graph, older, newer, accept, plicp);
  if (!c.edge) return c;
  const CPose2D correction = c.edge->z - c.predicted;
  if (correction.norm() > p.max_correction_xy ||
      std::abs(mrpt::math::wrapToPi(correction.phi())) > p.max_correction_theta)
  {
    c.verdict = LoopCheck::Verdict::GateRejected;
    c.edge.reset();
  }
  return c;
}

RefinementEdges refinementEdges(const graph::PoseGraph& graph, const std::function<LoopNode(size_t)>& node,
                                const FinalRefinementParams& p, const plicp::PlicpParams& plicp)
{
  RefinementEdges found;
  for (const auto& [i, j] : unlinkedClosePairs(graph, p.radius, static_cast<size_t>(p.max_pairs_per_node)))
  {
    LoopCheck check = verifyRefinementPair(graph, node(i), node(j), p, plicp);
    found.pairs++;
    if (check.edge) found.edges.push_back(std::move(*check.edge));
  }
  return found;
}

}  // namespace swslam::loop
