#pragma once
// When the graph module optimizes the whole graph (paper sec. III-B: after a loop closure).
// While loops keep coming, node after node, one full optimization per `interval` nodes is
// enough: a loop accepted sooner after the last full optimization is kept pending, and its
// node gets the sliding window (which holds the loop edges of its nodes, their old ends
// fixed). The pending full optimization runs at the first node `interval` nodes after the
// last one, whether or not that node closes a loop itself. With interval 1, every node that
// closes a loop that corrects the graph optimizes the whole graph.
//
// Only a loop that disagrees with the graph asks for a full optimization (loopCorrectsGraph):
// when a path is driven again, each new node already sits where its loops say, the window
// absorbs them, and optimizing the whole graph again and again would only cost time, growing
// with the graph.

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <optional>

namespace swslam::system
{
/** True if a loop measurement `measured` (pose of its newer node in the older node's frame)
 * differs from the graph's current relative pose `graph_relative` by more than `xy` [m] in
 * translation or `theta` [rad] in rotation (movedBeyond(); the loop edge's residual at the
 * current graph, as se2Error() has it): the loop would move the graph, and only the whole graph's
 * optimization spreads such a correction along the loop. With xy = theta = 0, true for every
 * loop (the paper's rule). */
bool loopCorrectsGraph(const mrpt::poses::CPose2D& graph_relative,
                       const mrpt::poses::CPose2D& measured, double xy, double theta);

class FullOptimizationSchedule
{
 public:
  /** Throws std::invalid_argument if `interval` is 0. */
  explicit FullOptimizationSchedule(size_t interval);

  /** Node `id` (increasing from call to call) was added with `correcting_loops` new loop
   * edges that correct the graph (loopCorrectsGraph): true if the whole graph is to be
   * optimized now (then it counts as done). */
  bool fullNow(size_t id, size_t correcting_loops);

  /** A full optimization ran at node `id` outside the schedule (the end of a run): nothing
   * is pending any more. */
  void ranFull(size_t id);

  /** Loops were accepted since the last full optimization. */
  bool pending() const { return pending_; }

 private:
  size_t interval_;
  std::optional<size_t> last_full_;
  bool pending_ = false;
};

}  // namespace swslam::system
