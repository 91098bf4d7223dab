#include <swslam/graph/edge_kind.h>

namespace swslam::graph
{
namespace
{
const char* const kKindNames[] = {"consecutive", "dense_neighbour", "loop", "odometry_prior"};
}

const char* edgeKindName(EdgeKind kind) { return kKindNames[static_cast<int>(kind)]; }

std::optional<EdgeKind> edgeKindFromName(const std::string& name)
{
  for (int k = 0; k < kEdgeKindCount; ++k)
    if (name == kKindNames[k]) return static_cast<EdgeKind>(k);
  return std::nullopt;
}

}  // namespace swslam::graph
