#pragma once
// When the graph module optimizes the whole graph (paper sec. III-B: after a loop closure).
// While loops keep coming, node after node, one full optimization per `interval` nodes is
// enough: a loop accepted sooner after the last full optimization is kept pending, and its
// node gets the sliding window (which holds the loop edges of its nodes, their old ends
// fixed). The pending full optimization runs at the first node `interval` nodes after the
// last one, whether or not that node closes a loop itself. With interval 1, every node that
// closes a loop optimizes the whole graph.

#include <cstddef>
#include <optional>

namespace swslam
{
class FullOptimizationSchedule
{
 public:
  /** Throws std::invalid_argument if `interval` is 0. */
  explicit FullOptimizationSchedule(size_t interval);

  /** Node `id` (increasing from call to call) was added with `accepted_loops` new loop
   * edges: true if the whole graph is to be optimized now (then it counts as done). */
  bool fullNow(size_t id, size_t accepted_loops);

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

}  // namespace swslam
