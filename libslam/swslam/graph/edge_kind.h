#pragma once
// The kind of a pose-graph constraint: decides whether the optimizer robustifies it.

#include <optional>
#include <string>

namespace swslam::graph
{
enum class EdgeKind
{
  Consecutive,     ///< node k-1 -> k from scan matching (robustified in the paper)
  DenseNeighbour,  ///< extra connection to a nearby node (paper Fig. 2)
  Loop,            ///< loop closure
  OdometryPrior    ///< wheel odometry or another prior between nodes
};

/** The number of kinds (EdgeKind values are 0 .. kEdgeKindCount - 1). */
constexpr int kEdgeKindCount = 4;

/** "consecutive", "dense_neighbour", "loop", "odometry_prior". */
const char* edgeKindName(EdgeKind kind);
std::optional<EdgeKind> edgeKindFromName(const std::string& name);

}  // namespace swslam::graph
