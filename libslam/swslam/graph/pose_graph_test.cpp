// The pose-graph wrapper: validation on insertion, adjacency, copies that own their edges.
#include <swslam/graph/pose_graph.h>

#include <gtest/gtest.h>

#include <cmath>

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
