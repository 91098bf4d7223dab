#pragma once
// Rivals (doc/loop-closure.md, "Rivals"): a tracking decision kept open. Where the tracking
// search had a second peak almost as high as the one it kept (a left turn taken for a right
// one at a symmetric crossing), the node's consecutive edge comes with its rival, the edge the
// other peak gives. Under the rival the node and every later node move rigidly, and loops
// looked for from there to the nodes before it tell which of the two the map agrees with.
// Pure functions: no threads, no config reading.

#include <swslam/graph/constraint.h>
#include <swslam/graph/pose_graph.h>
#include <swslam/loop/params.h>

#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace swslam::loop
{
/** The rigid motion T that the rival moves node rival.to and every later node by: T (+) x_to
 * is x_from (+) rival.z. */
mrpt::poses::CPose2D rivalMotion(const mrpt::poses::CPose2D& from_pose, const mrpt::poses::CPose2D& to_pose,
                                 const mrpt::poses::CPose2D& rival_z);

/** Whether an edge `from -> to` joins a node before `node` to `node` or a later one: the
 * edges that measured the decision at `node` one way. */
inline bool spans(size_t from, size_t to, size_t node) { return std::min(from, to) < node && std::max(from, to) >= node; }

/** Loop candidates for node `newest` under a rival of node `node` (< newest), `pose` being
 * newest's pose under it: the nodes before `node`, at least min_index_gap older than newest,
 * not merged, within max_distance of `pose`, nearest first, at most max_candidates. None when
 * loop closure is disabled. */
std::vector<size_t> rivalCandidates(const graph::PoseGraph& graph, size_t node, size_t newest,
                                    const mrpt::poses::CPose2D& pose, const LoopClosureParams& p);

}  // namespace swslam::loop
