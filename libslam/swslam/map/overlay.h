#pragma once
// What the map pictures (map.png, render.png) draw over the grid: the trajectory, the graph's
// nodes and its edges by kind, switched-off edges marked.

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
  std::vector<mrpt::poses::CPose2D> nodes;       ///< graph node (keyframe) poses
  std::vector<OverlayEdge> edges;
};

/** Throws std::invalid_argument naming the first edge whose index is beyond the nodes. */
void checkOverlay(const Overlay& overlay);

}  // namespace swslam::map
