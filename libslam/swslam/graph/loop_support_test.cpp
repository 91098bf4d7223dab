// Local consistency of loops (loop_support.h): the chain found from the consecutive edges, the
// cycle's chi-square distributed as chi-square with three degrees of freedom for loops that
// agree (which checks the composed covariance), large for a false one; true loops supported
// and random false ones not, on a synthetic walk; a group of false loops is one run.
#include <swslam/graph/loop_support.h>

#include <swslam/geometry/se2_error.h>
#include <swslam/graph/sliding_window.h>
#include <swslam/graph/synthetic.h>

#include "graph_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

using namespace swslam::graph;
using swslam::geometry::Pose2;

namespace
{
/** A straight chain of n poses 1 m apart, its edges' noise drawn with the information's
 * covariance, and loops a -> b measured with noise too. */
struct Corridor
{
  GraphProblem p;
  std::vector<Pose2> truth;
};

Corridor corridor(int n, std::mt19937& rng)
{
  Corridor c;
  std::normal_distribution<double> N(0, 1);
  for (int k = 0; k < n; ++k) c.truth.emplace_back(k * 1.0, 0.1 * std::sin(k), 0.2 * std::sin(0.5 * k));
  c.p.poses = c.truth;
  c.p.fixed.assign(n, 0);
  c.p.fixed[0] = 1;
  for (int k = 0; k + 1 < n; ++k)
  {
    GraphProblem::Edge e;
    e.i = k, e.j = k + 1, e.kind = EdgeKind::Consecutive, e.robust = true;
    const double sx = 0.05, sy = 0.03, st = 0.02;
    e.information = Eigen::Vector3d(1 / (sx * sx), 1 / (sy * sy), 1 / (st * st)).asDiagonal();
    // Noise in the measurement's own frame (se2_error.h): z = true (+) delta.
    e.z = swslam::geometry::composePose(swslam::geometry::relativePose(c.truth[k], c.truth[k + 1]),
                                        Pose2(sx * N(rng), sy * N(rng), st * N(rng)));
    c.p.edges.push_back(e);
  }
  return c;
}

GraphProblem::Edge loop(const Corridor& c, int a, int b, std::mt19937& rng, const Pose2& bias = Pose2::Zero())
{
  std::normal_distribution<double> N(0, 1);
  GraphProblem::Edge e;
  e.i = a, e.j = b, e.kind = EdgeKind::Loop, e.robust = true;
  const double s = 0.04, st = 0.01;
  e.information = Eigen::Vector3d(1 / (s * s), 1 / (s * s), 1 / (st * st)).asDiagonal();
  e.z = swslam::geometry::composePose(swslam::geometry::relativePose(c.truth[a], c.truth[b]),
                                      Pose2(s * N(rng) + bias.x(), s * N(rng) + bias.y(), st * N(rng) + bias.z()));
  return e;
}
}  // namespace

TEST(LoopSupport, TheChainFollowsTheConsecutiveEdges)
{
  std::mt19937 rng(1);
  Corridor c = corridor(8, rng);
  c.p.edges.push_back(loop(c, 1, 6, rng));
  const OdometryChain chain = odometryChain(c.p);
  for (int k = 0; k < 8; ++k)
  {
    EXPECT_EQ(chain.chain[k], 0);
    EXPECT_EQ(chain.position[k], k);
  }
  EXPECT_EQ(chain.next[7], -1);
  EXPECT_EQ(chain.previous[0], -1);
  EXPECT_TRUE(isLoopCandidate(c.p, chain, 7));
  EXPECT_FALSE(isLoopCandidate(c.p, chain, 0));
}

TEST(LoopSupport, AgreeingLoopsCloseCyclesOfChiSquareThree)
{
  // Two loops from a revisit (2 -> 30 and 5 -> 27, the second taken backwards as 27 -> 5):
  // over many noise draws the cycle's chi-square averages 3 if the composed covariance is right.
  std::mt19937 rng(7);
  double sum = 0;
  const int draws = 3000;
  for (int d = 0; d < draws; ++d)
  {
    Corridor c = corridor(40, rng);
    c.p.edges.push_back(loop(c, 2, 30, rng));
    c.p.edges.push_back(loop(c, 27, 5, rng));
    const OdometryChain chain = odometryChain(c.p);
    const double chi2 = cycleChi2(c.p, chain, c.p.edges.size() - 2, c.p.edges.size() - 1);
    ASSERT_GE(chi2, 0);
    sum += chi2;
  }
  EXPECT_NEAR(sum / draws, 3.0, 0.25);
}

TEST(LoopSupport, AFalseLoopDisagreesAndLoopsTooFarApartAreNotCompared)
{
  std::mt19937 rng(9);
  Corridor c = corridor(60, rng);
  c.p.edges.push_back(loop(c, 2, 30, rng));
  c.p.edges.push_back(loop(c, 4, 33, rng, Pose2(1.0, -0.5, 0.3)));  // false: 1 m and 17 degrees off
  c.p.edges.push_back(loop(c, 2, 50, rng));                          // 20 nodes from the others
  const OdometryChain chain = odometryChain(c.p);
  const size_t a = c.p.edges.size() - 3;
  EXPECT_GT(cycleChi2(c.p, chain, a, a + 1), 100.0);
  EXPECT_LT(cycleChi2(c.p, chain, a, a + 2), 0.0);
}

TEST(LoopSupport, TrueLoopsAreSupportedAndRandomFalseOnesAreNot)
{
  SyntheticGraph s = swslam::test::robustWalk();
  const std::vector<size_t> added = swslam::test::addAsManyFalseLoops(s.graph, 5);
  const std::set<size_t> false_loops(added.begin(), added.end());
  GraphOptimizerParams params;
  const GraphSubproblem sub = fullSubproblem(s.graph, params);
  const OdometryChain chain = odometryChain(sub.problem);
  const std::vector<int> support = loopAgreement(sub.problem, chain).support;
  size_t true_loops = 0, true_supported = 0, false_supported = 0;
  for (size_t k = 0; k < support.size(); ++k)
  {
    if (sub.problem.edges[k].kind != EdgeKind::Loop) continue;
    const bool is_false = false_loops.count(sub.edge_indices[k]) > 0;
    if (is_false)
      false_supported += support[k] > 0;
    else
      ++true_loops, true_supported += support[k] > 0;
  }
  EXPECT_GT(true_supported, 0.8 * true_loops) << true_supported << " of " << true_loops;
  EXPECT_LT(false_supported, 0.02 * added.size()) << false_supported << " of " << added.size();
}

TEST(LoopSupport, AGroupOfFalseLoopsIsOneRun)
{
  std::mt19937 rng(11);
  Corridor c = corridor(80, rng);
  const size_t first = c.p.edges.size();
  // Ten loops 10 -> 60 .. 19 -> 69 sharing one wrong offset: on a straight corridor they agree.
  for (int t = 0; t < 10; ++t) c.p.edges.push_back(loop(c, 10 + t, 60 + t, rng, Pose2(2.0, 1.0, 0.0)));
  c.p.edges.push_back(loop(c, 40, 75, rng));  // alone
  const OdometryChain chain = odometryChain(c.p);
  const std::vector<int> runs = loopAgreement(c.p, chain).runs;
  std::set<int> group;
  for (size_t k = first; k < first + 10; ++k) group.insert(runs[k]);
  EXPECT_EQ(group.size(), 1u);
  EXPECT_GE(*group.begin(), 0);
  EXPECT_NE(runs[first + 10], *group.begin());
  EXPECT_EQ(runs[0], -1);  // a step of the chain
}
