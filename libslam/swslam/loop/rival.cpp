#include <swslam/loop/rival.h>

#include <algorithm>
#include <utility>

namespace swslam::loop
{
using mrpt::poses::CPose2D;

CPose2D rivalMotion(const CPose2D& from_pose, const CPose2D& to_pose, const CPose2D& rival_z)
{
  return (from_pose + rival_z) + (-to_pose);
}

std::vector<size_t> rivalCandidates(const graph::PoseGraph& graph, size_t node, size_t newest, const CPose2D& pose,
                                    const LoopClosureParams& p)
{
  const auto gap = static_cast<size_t>(std::max(0, p.min_index_gap));
  if (!p.enabled || p.max_candidates <= 0 || newest < gap) return {};
  std::vector<std::pair<double, size_t>> near;
  const auto& nodes = graph.network().nodes;
  for (auto it = nodes.begin(); it != nodes.end() && it->first < node && it->first + gap <= newest; ++it)
  {
    if (graph.isMerged(it->first)) continue;
    const double d = (it->second.translation() - pose.translation()).norm();
    if (d <= p.max_distance) near.emplace_back(d, it->first);
  }
  std::sort(near.begin(), near.end());
  near.resize(std::min(near.size(), static_cast<size_t>(p.max_candidates)));
  std::vector<size_t> ids;
  for (const auto& n : near) ids.push_back(n.second);
  return ids;
}

}  // namespace swslam::loop
