#pragma once
// Pose-graph test worlds shared by the graph module's tests.

#include <swslam/graph/synthetic.h>

#include <vector>

namespace swslam::test
{
/** The 400-node grid walk of the robust back ends' tests (1200 edges, seed 21). */
inline graph::SyntheticGraph robustWalk()
{
  graph::SyntheticGraphOptions o;
  o.nodes = 400;
  o.total_edges = 1200;
  o.seed = 21;
  return graph::makeGridWalkGraph(o);
}

/** As many random false loops as the graph has true ones (seed given); their edge indices. */
inline std::vector<size_t> addAsManyFalseLoops(graph::PoseGraph& g, unsigned seed, bool grouped = false)
{
  graph::FalseLoopOptions fo;
  fo.count = graph::loopEdgeCount(g);
  fo.grouped = grouped;
  fo.seed = seed;
  return graph::addFalseLoops(g, fo);
}
}  // namespace swslam::test
