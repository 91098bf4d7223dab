#include "swslam/loop/final_refinement.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace swslam
{
using mrpt::poses::CPose2D;

std::vector<std::pair<size_t, size_t>> unlinkedClosePairs(const PoseGraph& graph, double radius)
{
  std::vector<std::pair<size_t, size_t>> pairs;
  const auto ids = graph.nodeIds();
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
      if ((graph.pose(j).translation() - here).norm() <= radius &&
          !std::binary_search(linked.begin(), linked.end(), j))
        pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

LoopCheck verifyRefinementPair(const PoseGraph& graph, const LoopNode& older, const LoopNode& newer,
                               const FinalRefinementParams& p, const PlicpParams& plicp)
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

std::vector<LoopCheck> refinementChecks(const PoseGraph& graph,
                                        const std::function<LoopNode(size_t)>& node,
                                        const FinalRefinementParams& p, const PlicpParams& plicp)
{
  std::vector<LoopCheck> checks;
  for (const auto& [i, j] : unlinkedClosePairs(graph, p.radius))
    checks.push_back(verifyRefinementPair(graph, node(i), node(j), p, plicp));
  return checks;
}

}  // namespace swslam
