#pragma once
// What the map pictures (map.png, render.png) draw over the grid: the trajectory (the scans the
// prediction placed marked), the graph's nodes and its edges by kind, switched-off edges marked.

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <vector>

namespace swslam::map
{
/** The kind of a drawn edge (the graph's edge kinds, without depending on the graph module). */
enum class EdgeLook
{
  Consecutive,     ///< node k-1 -> k
  DenseNeighbour,  ///< a nearby node's extra connection
  Loop,            ///< loop closure
  Prior            ///< odometry or another prior
};

struct OverlayEdge
{
  size_t from = 0, to = 0;  ///< indices into Overlay::nodes
  EdgeLook look = EdgeLook::Consecutive;
  bool switched_off = false;  ///< the robust kernel switched it off (weight ~0)
};

struct Overlay
{
  std::vector<mrpt::poses::CPose2D> trajectory;  ///< every scan's pose, in order
  /** Per trajectory pose: the prediction placed it (tracked by fallback, or decided along a
   * direction its match could not), not the scans alone; drawn apart. Empty: none marked. */
  std::vector<bool> by_prediction;
  std::vector<mrpt::poses::CPose2D> nodes;  ///< graph node (keyframe) poses
  std::vector<OverlayEdge> edges;

  /** Whether the segment into trajectory pose i is drawn as placed by the prediction. */
  bool segmentByPrediction(size_t i) const { return i < by_prediction.size() && by_prediction[i]; }
  /** How many trajectory poses the prediction placed. */
  size_t countByPrediction() const;
};

/** Throws std::invalid_argument naming the first edge whose index is beyond the nodes, or
 * by_prediction's size if it is neither empty nor the trajectory's. */
void checkOverlay(const Overlay& overlay);

}  // namespace swslam::map
