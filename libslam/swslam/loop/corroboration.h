#pragma once
// Loop corroboration (doc/loop-closure.md, step 4): a verified loop becomes a graph edge only
// once a second verified loop nearby agrees with it through the graph (loopPairChi2). The
// verified loops of the last `consistency_window` nodes wait here for a partner. Owned by the
// graph module's thread; not thread-safe.

#include <swslam/graph/constraint.h>
#include <swslam/loop/consistency.h>
#include <swslam/loop/params.h>

#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <vector>

namespace swslam::loop
{
class LoopCorroboration
{
 public:
  explicit LoopCorroboration(const LoopClosureParams& p) : params_(p) {}

  /** The loops verified at node `newest` go in; out come the edges to add now: each new loop
   * that agrees with a waiting or another new one (old nodes and new nodes each within
   * consistency_window ids), and each waiting loop the first time it is agreed with. Loops
   * whose new node is more than consistency_window older than `newest` stop waiting. With
   * consistency_window = 0 every verified loop comes straight out. `pose(id)`: the graph's
   * node pose; `path_length(id)`: the distance travelled up to the node (local drift). */
  std::vector<graph::Constraint> add(size_t newest, const std::vector<graph::Constraint>& verified,
                               const std::function<mrpt::poses::CPose2D(size_t)>& pose,
                               const std::function<double(size_t)>& path_length);

  size_t waiting() const { return pending_.size(); }

 private:
  struct Pending
  {
    graph::Constraint edge;
    LoopEdgeMeasure measure;
    bool added = false;
  };
  const LoopClosureParams params_;
  std::vector<Pending> pending_;
};

}  // namespace swslam::loop
