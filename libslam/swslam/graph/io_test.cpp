// Reading and writing pose graphs: g2o and TORO information layouts, round trips, MRPT
// compatibility, and bad input (skipped lines with their numbers, or errors naming the line).
#include <swslam/graph/io.h>

#include "test_support.h"

#include <mrpt/graphs/CNetworkOfPoses.h>

#include <gtest/gtest.h>

#include <sstream>

namespace
{
swslam::graph::PoseGraph read(const std::string& text, swslam::graph::GraphLoadReport* rep = nullptr)
{
  std::istringstream in(text);
  return swslam::graph::readGraph(in, "test.graph", rep);
}

const char* kVertices = "VERTEX2 0 0 0 0\nVERTEX2 1 1 0 0\nVERTEX2 2 2 0 0\n";

std::string errorOf(const std::string& text)
{
  try
  {
    read(text);
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(GraphIo, ReadsTheInformationMatrixInG2oAndToroOrder)
{
  // The same matrix [[11 12 13] [12 22 23] [13 23 33]] in both layouts.
  const auto g = read(std::string(kVertices) +
                      "EDGE_SE2 0 1 1 0 0  11 12 13 22 23 33\n"
                      "EDGE2    1 2 1 0 0  11 12 22 33 13 23\n");
  ASSERT_EQ(g.edgeCount(), 2u);
  for (size_t k = 0; k < 2; ++k)
  {
    const auto& I = g.edge(k).measurement->cov_inv;
    EXPECT_EQ(I(0, 0), 11);
    EXPECT_EQ(I(0, 1), 12);
    EXPECT_EQ(I(0, 2), 13);
    EXPECT_EQ(I(1, 1), 22);
    EXPECT_EQ(I(1, 2), 23);
    EXPECT_EQ(I(2, 2), 33);
    EXPECT_EQ(I(2, 1), 23);
  }
}

TEST(GraphIo, MrptSampleGraphLoadsWithPositiveDefiniteInformation)
{
  // MRPT's own loader reads these TORO EDGE2 lines in g2o order and gets a singular matrix
  // (1 0 1 1 0 0 -> I33 = 0); in TORO order the information is the identity.
  swslam::graph::GraphLoadReport rep;
  const auto g = swslam::graph::loadGraph(std::string(SWSLAM_MRPT_DATASETS) + "/graph_2d_circle_50nodes.graph", &rep);
  EXPECT_EQ(rep.vertices, 50u);
  EXPECT_EQ(rep.edges, 101u);
  EXPECT_EQ(rep.skipped_lines, 0u);
  EXPECT_TRUE(g.edge(0).measurement->cov_inv.asEigen().isIdentity());
  EXPECT_EQ(g.edge(0).kind, swslam::graph::EdgeKind::Consecutive);  // 0 -> 1
  EXPECT_EQ(g.edge(2).kind, swslam::graph::EdgeKind::Loop);         // 0 -> 25
}

TEST(GraphIo, RoundTripIsExactAndMrptReadsOurOutput)
{
  auto g = read(std::string(kVertices) + "FIX 1\n" +
                "EDGE_SE2 0 1 1.000000000000001 0.1 -3.1 100 1 2 200 3 50 # kind=dense_neighbour\n"
                "EDGE_SE2 0 2 2 0.3 0.2 10 0 0 10 0 5\n");
  g.setPose(2, mrpt::poses::CPose2D(1.0 / 3.0, -2e-17, M_PI - 1e-9));
  const std::string path = swslam::test::tempDir("graph_io") + "/out.g2o";
  swslam::graph::saveGraph(g, path);
  const auto back = swslam::graph::loadGraph(path);
  EXPECT_EQ(back.root(), 1u);
  ASSERT_EQ(back.edgeCount(), 2u);
  EXPECT_EQ(back.edge(0).kind, swslam::graph::EdgeKind::DenseNeighbour);
  EXPECT_EQ(back.edge(1).kind, swslam::graph::EdgeKind::Loop);
  for (const auto id : g.nodeIds())
  {
    EXPECT_EQ(back.pose(id).x(), g.pose(id).x());
    EXPECT_EQ(back.pose(id).y(), g.pose(id).y());
    EXPECT_EQ(back.pose(id).phi(), g.pose(id).phi());
  }
  for (size_t k = 0; k < 2; ++k)
  {
    EXPECT_EQ(back.edge(k).measurement->mean.x(), g.edge(k).measurement->mean.x());
    EXPECT_EQ(back.edge(k).measurement->cov_inv, g.edge(k).measurement->cov_inv);
  }
  mrpt::graphs::CNetworkOfPoses2DInf mrpt_graph;
  mrpt_graph.loadFromTextFile(path);
  EXPECT_EQ(mrpt_graph.nodeCount(), 3u);
  EXPECT_EQ(mrpt_graph.edgeCount(), 2u);
  EXPECT_EQ(mrpt_graph.edges.begin()->second.cov_inv(1, 2), 3);
}

TEST(GraphIo, GarbageLinesAreSkippedWithTheirLineNumbers)
{
  swslam::graph::GraphLoadReport rep;
  const auto g = read(std::string(kVertices) +      // lines 1-3
                          "# a comment\n"           // 4: not counted
                          "hello world\n"           // 5
                          "EDGE2 0 1 1 0\n"         // 6: too few fields
                          "EDGE2 0 1 1 0 0 1 0 1 1 0 0 extra\n"  // 7: too many
                          "EQUIV 1 2\n"             // 8
                          "VERTEX2 x 1 2 3\n"       // 9
                          "EDGE2 0 1 1 0 0 1 0 1 1 0 0\n",  // 10: good
                      &rep);
  EXPECT_EQ(g.nodeCount(), 3u);
  EXPECT_EQ(g.edgeCount(), 1u);
  EXPECT_EQ(rep.skipped_lines, 5u);
  EXPECT_EQ(rep.skipped_line_numbers, (std::vector<size_t>{5, 6, 7, 8, 9}));
  EXPECT_NE(rep.skip_reasons[0].find("hello"), std::string::npos);
}

TEST(GraphIo, BadRecordsAreErrorsNamingTheLine)
{
  const std::string v = kVertices;
  EXPECT_NE(errorOf(v + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 0\n").find("not positive definite"),
            std::string::npos);
  EXPECT_NE(errorOf(v + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 -2\n").find("not positive definite"),
            std::string::npos);
  EXPECT_NE(errorOf(v + "EDGE_SE2 0 1 nan 0 0 1 0 0 1 0 1\n").find("not finite"), std::string::npos);
  EXPECT_NE(errorOf(v + "VERTEX2 3 nan 0 0\n").find("test.graph:4: node 3: pose is not finite"),
            std::string::npos);
  EXPECT_NE(errorOf(v + "VERTEX2 2 0 0 0\n").find("duplicate"), std::string::npos);
  EXPECT_NE(errorOf(v + "EDGE2 1 1 1 0 0 1 0 1 1 0 0\n").find("two different nodes"),
            std::string::npos);
  EXPECT_NE(errorOf(v + "FIX 9\n").find("FIX names missing node 9"), std::string::npos);
  EXPECT_NE(errorOf("garbage only\n").find("no vertex and no edge"), std::string::npos);
  EXPECT_THROW(swslam::graph::loadGraph("/nonexistent/x.graph"), std::runtime_error);
}

TEST(GraphIo, AnEdgeTheKernelSwitchedOffIsMarkedAndStillLoadsWithItsKind)
{
  const auto g = read(std::string(kVertices) + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1 # kind=consecutive\n"
                                               "EDGE_SE2 0 2 5 5 1 1 0 0 1 0 1 # kind=loop\n");
  std::ostringstream out;
  swslam::graph::writeGraph(g, out, {1});
  const std::string text = out.str();
  EXPECT_NE(text.find("# kind=loop switched_off\n"), std::string::npos) << text;
  EXPECT_NE(text.find("# kind=consecutive\n"), std::string::npos) << text;
  swslam::graph::GraphLoadReport rep;
  const auto back = read(text, &rep);
  ASSERT_EQ(back.edgeCount(), 2u);
  EXPECT_EQ(back.edge(1).kind, swslam::graph::EdgeKind::Loop);
  EXPECT_EQ(rep.switched_off, std::vector<size_t>{1});
  mrpt::graphs::CNetworkOfPoses2DInf mrpt_graph;
  const std::string path = swslam::test::tempDir("graph_io_off") + "/off.g2o";
  swslam::graph::saveGraph(g, path, {1});
  mrpt_graph.loadFromTextFile(path);
  EXPECT_EQ(mrpt_graph.edgeCount(), 2u);
}

TEST(GraphIo, AMergedNodeRoundTripsWithItsAttachment)
{
  auto g = read(std::string(kVertices) + "VERTEX2 3 0.2 0.1 0\n"
                                         "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1 # kind=consecutive\n"
                                         "EDGE_SE2 1 2 1 0 0 1 0 0 1 0 1 # kind=consecutive\n"
                                         "EDGE_SE2 2 3 -1.8 0.1 0 1 0 0 1 0 1 # kind=consecutive\n"
                                         "EDGE_SE2 0 3 0.2 0.1 0 50 0 0 50 0 50 # kind=loop\n");
  mrpt::math::CMatrixDouble33 info;
  info.setIdentity();
  info *= 50.0;
  const mrpt::poses::CPosePDFGaussianInf z(mrpt::poses::CPose2D(0.2, 0.1, 0), info);
  g.merge(3, 0, z);
  std::ostringstream out;
  swslam::graph::writeGraph(g, out);
  EXPECT_NE(out.str().find("EDGE_SE2 0 3 0.2"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("# kind=merged\n"), std::string::npos) << out.str();
  const auto back = read(out.str());
  ASSERT_TRUE(back.isMerged(3));
  EXPECT_EQ(back.merged().at(3).anchor, 0u);
  EXPECT_DOUBLE_EQ(back.merged().at(3).z.cov_inv(1, 1), 50.0);
  ASSERT_EQ(back.edgeCount(), g.edgeCount());
  for (size_t k = 0; k < g.edgeCount(); ++k)
  {
    EXPECT_EQ(back.edge(k).from, g.edge(k).from);
    EXPECT_EQ(back.edge(k).to, g.edge(k).to);
    EXPECT_EQ(back.edge(k).measurement->mean.x(), g.edge(k).measurement->mean.x());
  }
  // An attachment into a node that is not there, or of the root, names its line.
  const std::string bad = std::string(kVertices) + "EDGE_SE2 1 0 1 0 0 1 0 0 1 0 1 # kind=merged\n";
  EXPECT_THROW(read(bad), std::runtime_error);
}

TEST(GraphIo, VerticesOnlyTheEdgesNameArePlacedAlongTheOdometryChain)
{
  // An edge-only g2o file (SE-Sync's CSAIL, M3500): the chain 0-1-2, a gap, 3-4, a loop 1 -> 3
  // that bridges the gap, and a piece 7-8 no edge joins to the rest.
  const std::string text = "EDGE_SE2 0 1 1 0 1.5707963267948966 1 0 0 1 0 1\n"
                           "EDGE_SE2 1 2 2 0 0 1 0 0 1 0 1\n"
                           "EDGE_SE2 1 3 0 1 0 1 0 0 1 0 1\n"  // a loop: 3 is 1 m to the left of 1
                           "EDGE_SE2 3 4 1 0 0 1 0 0 1 0 1\n"
                           "EDGE_SE2 0 2 9 9 0 1 0 0 1 0 1\n"  // a loop the chain already placed 2 by
                           "EDGE_SE2 7 8 0.5 0 0 1 0 0 1 0 1\n";
  swslam::graph::GraphLoadReport rep;
  const auto g = read(text, &rep);
  EXPECT_EQ(rep.placed_vertices, 7u);
  EXPECT_EQ(rep.placed_pieces, 2u);  // the first vertex, and the piece 7-8
  auto near = [](const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b) {
    return (a.translation() - b.translation()).norm() < 1e-12 && std::abs(a.phi() - b.phi()) < 1e-12;
  };
  EXPECT_TRUE(near(g.pose(0), mrpt::poses::CPose2D()));
  EXPECT_TRUE(near(g.pose(1), mrpt::poses::CPose2D(1, 0, M_PI / 2)));
  EXPECT_TRUE(near(g.pose(2), mrpt::poses::CPose2D(1, 2, M_PI / 2))) << "along the chain, not the loop 0 -> 2";
  EXPECT_TRUE(near(g.pose(3), mrpt::poses::CPose2D(0, 0, M_PI / 2))) << "the gap bridged by the loop";
  EXPECT_TRUE(near(g.pose(4), mrpt::poses::CPose2D(0, 1, M_PI / 2)));
  EXPECT_TRUE(near(g.pose(7), mrpt::poses::CPose2D()));
  EXPECT_TRUE(near(g.pose(8), mrpt::poses::CPose2D(0.5, 0, 0)));
  // Given vertices stay as given; only the missing ones are placed, from them.
  const auto h = read("VERTEX_SE2 0 5 5 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n", &rep);
  EXPECT_EQ(rep.placed_vertices, 1u);
  EXPECT_EQ(rep.placed_pieces, 0u);
  EXPECT_TRUE(near(h.pose(1), mrpt::poses::CPose2D(6, 5, 0)));
}
