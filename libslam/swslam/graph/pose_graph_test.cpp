// The pose-graph wrapper: validation on insertion, adjacency, copies that own their edges.
#include <swslam/graph/pose_graph.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace
{
mrpt::poses::CPosePDFGaussianInf measurement(double x, double info = 1.0)
{
  mrpt::poses::CPosePDFGaussianInf z;
  z.mean = mrpt::poses::CPose2D(x, 0, 0);
  z.cov_inv.setIdentity();
  z.cov_inv *= info;
  return z;
}
}  // namespace

TEST(PoseGraph, AdjacencyListsEveryEdgeOfANode)
{
  swslam::graph::PoseGraph g;
  for (int k = 0; k < 4; ++k) g.addNode(k, mrpt::poses::CPose2D(k, 0, 0));
  g.addEdge(0, 1, measurement(1), swslam::graph::EdgeKind::Consecutive);
  g.addEdge(1, 2, measurement(1), swslam::graph::EdgeKind::Consecutive);
  g.addEdge(0, 2, measurement(2), swslam::graph::EdgeKind::Loop);
  g.addEdge(0, 2, measurement(2), swslam::graph::EdgeKind::DenseNeighbour);  // parallel edge
  EXPECT_EQ(g.edgesOf(0), (std::vector<size_t>{0, 2, 3}));
  EXPECT_EQ(g.edgesOf(2), (std::vector<size_t>{1, 2, 3}));
  EXPECT_TRUE(g.edgesOf(3).empty());
  EXPECT_EQ(g.network().edgeCount(), 4u);
  EXPECT_EQ(g.root(), 0u);
  EXPECT_EQ(g.newestNodes(2), (std::vector<swslam::graph::PoseGraph::TNodeID>{2, 3}));
  EXPECT_EQ(g.newestNodes(10).size(), 4u);
}

TEST(PoseGraph, CopiesOwnTheirMeasurements)
{
  swslam::graph::PoseGraph g;
  g.addNode(0, {});
  g.addNode(1, {});
  g.addEdge(0, 1, measurement(1, 5.0), swslam::graph::EdgeKind::Loop);
  auto copy = std::make_unique<swslam::graph::PoseGraph>(g);
  swslam::graph::PoseGraph assigned;
  assigned = *copy;
  EXPECT_NE(copy->edge(0).measurement, g.edge(0).measurement);
  copy.reset();  // the assigned graph must not point into the destroyed copy
  EXPECT_EQ(assigned.edge(0).measurement->cov_inv(0, 0), 5.0);
  EXPECT_EQ(&assigned.edge(0).measurement->mean, &assigned.network().edges.begin()->second.mean);
}

TEST(PoseGraph, RejectsBadInput)
{
  swslam::graph::PoseGraph g;
  EXPECT_THROW(g.addNode(0, mrpt::poses::CPose2D(NAN, 0, 0)), std::invalid_argument);
  g.addNode(0, {});
  g.addNode(1, {});
  EXPECT_THROW(g.addNode(1, {}), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 5, measurement(1), swslam::graph::EdgeKind::Loop), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 0, measurement(1), swslam::graph::EdgeKind::Loop), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 1, measurement(NAN), swslam::graph::EdgeKind::Loop), std::invalid_argument);
  EXPECT_THROW(g.addEdge(0, 1, measurement(1, -1.0), swslam::graph::EdgeKind::Loop), std::invalid_argument);
  auto asym = measurement(1);
  asym.cov_inv(0, 1) = 0.5;
  EXPECT_THROW(g.addEdge(0, 1, asym, swslam::graph::EdgeKind::Loop), std::invalid_argument);
  EXPECT_THROW(g.setPose(0, mrpt::poses::CPose2D(0, INFINITY, 0)), std::invalid_argument);
  EXPECT_THROW(g.setPose(9, {}), std::invalid_argument);
  EXPECT_THROW(g.edgesOf(9), std::invalid_argument);
  EXPECT_THROW(g.setRoot(9), std::invalid_argument);
  EXPECT_EQ(g.edgeCount(), 0u);
}

TEST(EdgeKind, NamesRoundTrip)
{
  for (auto k : {swslam::graph::EdgeKind::Consecutive, swslam::graph::EdgeKind::DenseNeighbour,
                 swslam::graph::EdgeKind::Loop, swslam::graph::EdgeKind::OdometryPrior})
    EXPECT_EQ(swslam::graph::edgeKindFromName(swslam::graph::edgeKindName(k)), k);
  EXPECT_FALSE(swslam::graph::edgeKindFromName("loops").has_value());
}

namespace
{
/** Every edge is listed once at each end, and no edge names a merged node. */
void expectConsistent(const swslam::graph::PoseGraph& g)
{
  std::map<swslam::graph::PoseGraph::TNodeID, std::vector<size_t>> listed;
  for (size_t k = 0; k < g.edgeCount(); ++k)
  {
    const auto& e = g.edge(k);
    EXPECT_FALSE(g.isMerged(e.from) || g.isMerged(e.to)) << "edge " << k;
    listed[e.from].push_back(k);
    listed[e.to].push_back(k);
  }
  for (const auto id : g.nodeIds())
  {
    auto mine = g.edgesOf(id);
    std::sort(mine.begin(), mine.end());
    EXPECT_EQ(mine, listed[id]) << "node " << id;
  }
  EXPECT_EQ(g.network().edgeCount(), g.edgeCount());
}
}  // namespace

TEST(PoseGraph, AMergedNodesEdgesAndLaterOnesAreCarriedToItsAnchor)
{
  using swslam::graph::EdgeKind;
  swslam::graph::PoseGraph g;
  for (int k = 0; k < 5; ++k) g.addNode(k, mrpt::poses::CPose2D(k, 0, 0));
  g.addEdge(0, 1, measurement(1), EdgeKind::Consecutive);
  g.addEdge(1, 2, measurement(1), EdgeKind::Consecutive);
  g.addEdge(2, 3, measurement(1), EdgeKind::Consecutive);
  g.addEdge(3, 4, measurement(1), EdgeKind::Consecutive);
  g.addEdge(1, 4, measurement(3), EdgeKind::Loop);
  g.addEdge(2, 4, measurement(2), EdgeKind::Loop);
  // Node 4 sits 0.1 m ahead of node 1 by the attachment (its loop said 3 m: a revisit).
  g.merge(4, 1, measurement(0.1, 100));
  EXPECT_TRUE(g.isMerged(4));
  EXPECT_EQ(g.liveNodeCount(), 4u);
  EXPECT_DOUBLE_EQ(g.pose(4).x(), 1.1);
  EXPECT_TRUE(g.edgesOf(4).empty());
  // 3 -> 4 became 3 -> 1 (1 m then 0.1 m back), 2 -> 4 became 2 -> 1; the loop 1 -> 4 is the attachment.
  EXPECT_EQ(g.edgeCount(), 5u);
  expectConsistent(g);
  bool carried = false;
  for (size_t k = 0; k < g.edgeCount(); ++k)
    if (g.edge(k).from == 3 && g.edge(k).to == 1)
    {
      carried = true;
      EXPECT_NEAR(g.edge(k).measurement->mean.x(), 0.9, 1e-12);
      EXPECT_EQ(g.edge(k).kind, EdgeKind::Consecutive);
      EXPECT_LT(g.edge(k).measurement->cov_inv(0, 0), 1.0);  // the attachment's uncertainty added
    }
  EXPECT_TRUE(carried);
  // A later edge naming node 4 is carried; one that folds into node 1 is not kept.
  g.addNode(5, mrpt::poses::CPose2D(2.1, 0, 0));
  const auto later = g.addEdge(4, 5, measurement(1), EdgeKind::Consecutive);
  ASSERT_TRUE(later.has_value());
  EXPECT_EQ(g.edge(*later).from, 1u);
  EXPECT_NEAR(g.edge(*later).measurement->mean.x(), 1.1, 1e-12);
  EXPECT_FALSE(g.addEdge(1, 4, measurement(0.1), EdgeKind::Loop).has_value());
  expectConsistent(g);
  // Moving the anchor moves the merged node; a copy keeps the merge.
  g.setPose(1, mrpt::poses::CPose2D(1, 1, 0));
  g.placeMergedInto(1);
  EXPECT_DOUBLE_EQ(g.pose(4).y(), 1.0);
  const swslam::graph::PoseGraph copy = g;
  EXPECT_TRUE(copy.isMerged(4));
  EXPECT_EQ(copy.merged().at(4).anchor, 1u);
  expectConsistent(copy);
}

TEST(PoseGraph, AMergeThatWouldBreakTheGraphIsRefused)
{
  swslam::graph::PoseGraph g;
  for (int k = 0; k < 4; ++k) g.addNode(k, mrpt::poses::CPose2D(k, 0, 0));
  EXPECT_THROW(g.merge(0, 1, measurement(1)), std::invalid_argument);  // the root
  EXPECT_THROW(g.merge(2, 2, measurement(1)), std::invalid_argument);
  EXPECT_THROW(g.merge(2, 9, measurement(1)), std::invalid_argument);
  EXPECT_THROW(g.merge(2, 1, measurement(1, -1.0)), std::invalid_argument);
  g.merge(2, 1, measurement(1));
  EXPECT_THROW(g.merge(2, 1, measurement(1)), std::invalid_argument);  // merged already
  EXPECT_THROW(g.merge(3, 2, measurement(1)), std::invalid_argument);  // into a merged node
  EXPECT_THROW(g.merge(1, 3, measurement(1)), std::invalid_argument);  // an anchor
}
