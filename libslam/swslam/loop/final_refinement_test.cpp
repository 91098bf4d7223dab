// Final refinement: the unlinked close pairs of a graph, and the verification of each pair on
// the synthetic cluttered scene (fixed seeds): a revisit gets an edge, unrelated scans do not.
#include <swslam/loop/final_refinement.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose3D.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "loop_test_support.h"

using namespace swslam;
using namespace swslam::loop;
using mrpt::poses::CPose2D;
using Verdict = LoopCheck::Verdict;

namespace
{
constexpr double kDeg = M_PI / 180;
const CPose2D kMount(0.3, 0.1, 0.05);

LoopNode nodeAt(const test::World& world, size_t id, const CPose2D& vehicle, std::mt19937& rng)
{
  return test::mountedNode(world, id, vehicle, 0.0, rng, kMount);
}

using test::weakEdge;

/** Node 0 scanned at `a`; node 1 revisits it 0.94 m away, turned 25 deg, placed in the graph
 * off by `offset`; node 2 is placed next to node 0 but its scan was taken 15 m away; node 3
 * is 20 m away. Edges: 2 - 3 only. */
struct Scene
{
  test::World world = test::clutteredWorld(5);
  CPose2D a{-10, -3, 0.1}, b{-9.2, -2.5, 0.1 + 25 * kDeg};
  graph::PoseGraph graph;
  std::vector<LoopNode> nodes;

  Scene(const CPose2D& offset, unsigned seed)
  {
    std::mt19937 rng(seed);
    nodes = {nodeAt(world, 0, a, rng), nodeAt(world, 1, b, rng),
             nodeAt(world, 2, CPose2D(5, -3.5, 0.1), rng), nodeAt(world, 3, CPose2D(10, -3, 0), rng)};
    graph.addNode(0, a);
    graph.addNode(1, b + offset);
    graph.addNode(2, a + CPose2D(0.6, -0.8, 3 * kDeg));
    graph.addNode(3, CPose2D(10, -3, 0));
    graph.addEdge(2, 3, weakEdge(graph.pose(3) - graph.pose(2)), graph::EdgeKind::Consecutive);
  }
  std::function<LoopNode(size_t)> node() const
  {
    return [this](size_t id) { return nodes.at(id); };
  }
};
}  // namespace

TEST(UnlinkedClosePairs, RespectRadiusAndExistingEdgesAtAnyIdGap)
{
  graph::PoseGraph g;
  for (size_t k = 0; k < 6; k++) g.addNode(k, CPose2D(double(k), 0, 0));  // x = id
  g.addNode(100, CPose2D(0.5, 0.5, 0));                                 // ~0.7 m from 0 and 1
  g.addEdge(0, 1, weakEdge(CPose2D(1, 0, 0)), graph::EdgeKind::Consecutive);
  g.addEdge(100, 1, weakEdge(CPose2D(0.5, -0.5, 0)), graph::EdgeKind::Loop);
  using P = std::pair<size_t, size_t>;
  EXPECT_EQ(unlinkedClosePairs(g, 1.0),
            (std::vector<P>{{0, 100}, {1, 2}, {2, 3}, {3, 4}, {4, 5}}));
  EXPECT_EQ(unlinkedClosePairs(g, 1.6),
            (std::vector<P>{{0, 100}, {1, 2}, {2, 3}, {2, 100}, {3, 4}, {4, 5}}));
  EXPECT_TRUE(unlinkedClosePairs(g, 0.5).empty());
  // At most one partner per newer node, the nearest: node 100 keeps 0 (0.71 m), not 2 (1.58 m).
  EXPECT_EQ(unlinkedClosePairs(g, 1.6, 1),
            (std::vector<P>{{0, 100}, {1, 2}, {2, 3}, {3, 4}, {4, 5}}));
  EXPECT_EQ(unlinkedClosePairs(g, 1.6, 0), unlinkedClosePairs(g, 1.6));
}

TEST(FinalRefinement, ARevisitGetsAnEdgeAndUnrelatedScansDoNot)
{
  const Scene s(CPose2D(0.05, -0.04, 0.5 * kDeg), 21);
  const FinalRefinementParams p;  // radius 3 m: pairs (0, 1), (0, 2), (1, 2)
  const auto found = refinementEdges(s.graph, s.node(), p, plicp::PlicpParams());
  EXPECT_EQ(found.pairs, 3u);
  ASSERT_EQ(found.edges.size(), 1u);
  const graph::Constraint& e = found.edges[0];
  EXPECT_EQ(e.from, 0u);
  EXPECT_EQ(e.to, 1u);
  EXPECT_EQ(e.kind, graph::EdgeKind::Loop);
  const CPose2D err = e.z - (s.b - s.a);
  EXPECT_LT(err.norm(), 0.02);
  EXPECT_LT(std::abs(mrpt::math::wrapToPi(err.phi())), 0.5 * kDeg);
  // The pairs with the unrelated scan 2: checked and rejected.
  for (size_t older : {0u, 1u})
  {
    const LoopCheck c = verifyRefinementPair(s.graph, s.nodes.at(older), s.nodes.at(2), p, plicp::PlicpParams());
    EXPECT_EQ(c.to, 2u);
    EXPECT_NE(c.verdict, Verdict::Accepted) << older << " d2 " << c.mahalanobis2;
    EXPECT_FALSE(c.edge.has_value());
  }
}

TEST(FinalRefinement, AMatchFartherFromTheGuessThanTheGateIsRejected)
{
  // The graph's guess is 0.4 m off; with a loose chi-square gate the match passes verifyLoop,
  // and only the correction gate decides.
  const Scene s(CPose2D(0.3, -0.25, 2 * kDeg), 22);
  FinalRefinementParams p;
  p.sigma_xy = 1.0;
  p.sigma_theta = 10 * kDeg;
  const LoopCheck near = verifyRefinementPair(s.graph, s.nodes[0], s.nodes[1], p, plicp::PlicpParams());
  EXPECT_EQ(near.verdict, Verdict::GateRejected);
  EXPECT_FALSE(near.edge.has_value());
  EXPECT_LE(near.mahalanobis2, p.chi2_gate);  // the chi-square gate alone would accept
  p.max_correction_xy = 1.0;
  const LoopCheck far = verifyRefinementPair(s.graph, s.nodes[0], s.nodes[1], p, plicp::PlicpParams());
  EXPECT_EQ(far.verdict, Verdict::Accepted);
  ASSERT_TRUE(far.edge.has_value());
  EXPECT_LT((far.edge->z - (s.b - s.a)).norm(), 0.02);
}

TEST(FinalRefinementParams, OutOfRangeValuesAreErrorsNamingTheKey)
{
  auto load = [](const std::string& key, const std::string& value) {
    mrpt::config::CConfigFileMemory cfg;
    cfg.write("final_refinement", key, value);
    FinalRefinementParams p;
    FinalRefinementParams::table().load(cfg, p);
  };
  EXPECT_NO_THROW(load("passes", "2"));
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"passes", "0"}, {"radius", "-1"}, {"min_inlier_fraction", "1.5"}, {"chi2_gate", "0"},
           {"sigma_xy", "0"}, {"sigma_theta_DEG", "0"}, {"max_correction_xy", "-0.1"}})
  {
    try
    {
      load(key, value);
      ADD_FAILURE() << key << " = " << value << " loaded";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(key.substr(0, key.find("_DEG"))), std::string::npos)
          << e.what();
    }
  }
}
