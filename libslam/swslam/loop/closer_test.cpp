// Loop closure: candidate selection on plain graphs, verification of revisits on a
// synthetic cluttered scene (fixed seeds), the gate's arithmetic, and the parameters.
#include <swslam/common/param_table.h>
#include <swslam/geometry/sensor_frame.h>
#include <swslam/loop/closer.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Dense>
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
const CPose2D kMount(0.3, 0.1, 0.05);  // off-centre, so frame mix-ups show
constexpr double kDeg = M_PI / 180;

LoopNode nodeAt(const test::World& world, size_t id, const CPose2D& vehicle, double path_length,
                std::mt19937& rng, const CPose2D& mount = kMount)
{
  return test::mountedNode(world, id, vehicle, path_length, rng, mount);
}

using test::weakEdge;

/** A revisit on the cluttered scene: node 0 at `a`, node 40 scanned at `b` but placed in the
 * graph at b moved by `graph_offset` (the drift). */
struct Revisit
{
  test::World world = test::clutteredWorld(5);
  CPose2D a{-10, -3, 0.1}, b{-9.2, -2.5, 0.1 + 25 * kDeg};
  graph::PoseGraph graph;
  LoopNode old_node, new_node;

  Revisit(const CPose2D& graph_offset, double path_gap, unsigned seed)
  {
    std::mt19937 rng(seed);
    old_node = nodeAt(world, 0, a, 0.0, rng);
    new_node = nodeAt(world, 40, b, path_gap, rng);
    graph.addNode(0, a);
    graph.addNode(40, b + graph_offset);
  }
  CPose2D truth() const { return b - a; }
};
}  // namespace

TEST(LoopCandidates, RespectGapDistanceCountAndExistingEdges)
{
  graph::PoseGraph g;
  for (size_t k = 0; k < 30; k++) g.addNode(k, CPose2D(double(k), 0, 0));  // x = id
  for (size_t k = 30; k < 50; k++) g.addNode(k, CPose2D(2.0, 1.0, 0));     // near, too recent
  g.addNode(50, CPose2D(2.2, 0.5, 0));
  LoopClosureParams p;  // gap 30 -> ids <= 20; within 5 m -> ids 0..7
  p.max_candidates = 3;
  EXPECT_EQ(loopCandidates(g, 50, p), (std::vector<size_t>{2, 3, 1}));
  p.max_candidates = 100;
  EXPECT_EQ(loopCandidates(g, 50, p), (std::vector<size_t>{2, 3, 1, 4, 0, 5, 6, 7}));
  p.max_distance = 0.9;  // node 2 is 0.54 m away, node 3 0.94 m
  EXPECT_EQ(loopCandidates(g, 50, p), (std::vector<size_t>{2}));
  p.min_index_gap = 49;  // only ids 0 and 1 are old enough
  p.max_distance = 5.0;
  EXPECT_EQ(loopCandidates(g, 50, p), (std::vector<size_t>{1, 0}));
  g.addEdge(1, 50, weakEdge(CPose2D(1.2, 0.5, 0)), graph::EdgeKind::DenseNeighbour);
  EXPECT_EQ(loopCandidates(g, 50, p), (std::vector<size_t>{0}));  // already linked
  p.enabled = false;
  EXPECT_TRUE(loopCandidates(g, 50, p).empty());
  EXPECT_TRUE(loopCandidates(g, 10, LoopClosureParams()).empty());  // nothing old enough
  EXPECT_THROW(loopCandidates(g, 99, LoopClosureParams()), std::invalid_argument);
}

TEST(LoopCandidates, WithNoneNearTheOneTheDriftExplainsBestIsLookedFor)
{
  // Nodes 0..9 along x, then a long way round (path length 10 m a node): node 60 is 8-17 m
  // from nodes 0..9 on the estimate, none within max_distance (5 m).
  graph::PoseGraph g;
  for (size_t k = 0; k < 10; k++) g.addNode(k, CPose2D(double(k), 0, 0));
  for (size_t k = 10; k < 60; k++) g.addNode(k, CPose2D(100.0, double(k), 0));
  g.addNode(60, CPose2D(8.0, 8.0, 0));
  const auto path = [](size_t id) { return 10.0 * static_cast<double>(id); };
  LoopClosureParams p;  // drift 3 cm/m: reach 3 x 0.03 x (600 - 10 k) m, 54 m for node 0
  EXPECT_TRUE(loopCandidates(g, 60, p).empty()) << "without path lengths: max_distance only";
  // Nodes 0..9 lie 8.0-12.8 m away within reaches of 54-45.9 m: node 7 (8.06 m of 47.7)
  // fits best, before node 6 (8.25 of 48.6) and node 8 (8.0 of 46.8).
  EXPECT_EQ(loopCandidates(g, 60, p, path), (std::vector<size_t>{7}));
  p.max_search_radius = 7.9;  // none within the search radius
  EXPECT_TRUE(loopCandidates(g, 60, p, path).empty());
  p.max_search_radius = 25;
  p.drift_xy_per_m = 0.004;  // reaches 7.2-6.1 m: none of them that far drifted
  EXPECT_TRUE(loopCandidates(g, 60, p, path).empty());
  p.drift_xy_per_m = 0.03;
  g.addNode(61, CPose2D(8.0, 4.0, 0));  // node 8 within max_distance: near candidates only
  EXPECT_EQ(loopCandidates(g, 61, p, path), (std::vector<size_t>{8, 7, 9}));
}

TEST(VerifyLoop, ATrueRevisitWithADriftedGraphIsAcceptedWithTheTruePose)
{
  const Revisit r(CPose2D(0.4, -0.3, 5 * kDeg), 20.0, 11);  // 0.5 m, 5 deg off after 20 m
  const LoopCheck c = verifyLoop(r.graph, r.old_node, r.new_node, LoopClosureParams(), plicp::PlicpParams());
  ASSERT_EQ(c.verdict, Verdict::Accepted) << toString(c.verdict) << " d2 " << c.mahalanobis2
                                          << " " << c.match.message;
  EXPECT_EQ(c.from, 0u);
  EXPECT_EQ(c.to, 40u);
  EXPECT_NEAR(c.path_gap, 20.0, 1e-12);
  EXPECT_LT(c.mahalanobis2, LoopClosureParams().chi2_gate);
  ASSERT_TRUE(c.edge.has_value());
  EXPECT_EQ(c.edge->kind, graph::EdgeKind::Loop);
  EXPECT_EQ(c.edge->from, 0u);
  EXPECT_EQ(c.edge->to, 40u);
  const CPose2D truth = r.truth();
  EXPECT_NEAR(c.edge->z.x(), truth.x(), 0.03);
  EXPECT_NEAR(c.edge->z.y(), truth.y(), 0.03);
  EXPECT_NEAR(c.edge->z.phi(), truth.phi(), 0.01);
  EXPECT_EQ(Eigen::LLT<Eigen::Matrix3d>(c.edge->information).info(), Eigen::Success);

  // The same match with a stricter overlap demand is refused for that reason.
  LoopClosureParams strict;
  strict.min_inlier_fraction = 1.0;
  EXPECT_EQ(verifyLoop(r.graph, r.old_node, r.new_node, strict, plicp::PlicpParams()).verdict,
            Verdict::PoorOverlap);
}

TEST(VerifyLoop, TheGateRejectsADriftTheTravelCannotExplain)
{
  // The same 0.5 m / 5 deg offset after only 2 m of travel: the match is right, the graph's
  // prediction is not plausible, so the pair is refused (d2 ~ 25 + 25 against 11.34).
  const Revisit near(CPose2D(0.4, -0.3, 5 * kDeg), 2.0, 12);
  const LoopCheck c = verifyLoop(near.graph, near.old_node, near.new_node, LoopClosureParams(), plicp::PlicpParams());
  EXPECT_EQ(c.verdict, Verdict::GateRejected) << toString(c.verdict) << " d2 " << c.mahalanobis2;
  EXPECT_GT(c.mahalanobis2, 30.0);
  EXPECT_NEAR(geometry::vehicleMotion(kMount, c.match.pose).x(), near.truth().x(), 0.03);
  EXPECT_FALSE(c.edge.has_value());

  // 1.5 m and 12 deg off after 5 m of travel (drift std 0.15 m, 1.5 deg).
  const Revisit far(CPose2D(1.2, 0.9, 12 * kDeg), 5.0, 13);
  const LoopCheck f = verifyLoop(far.graph, far.old_node, far.new_node, LoopClosureParams(), plicp::PlicpParams());
  EXPECT_EQ(f.verdict, Verdict::GateRejected) << toString(f.verdict) << " " << f.match.message;
  EXPECT_GT(f.mahalanobis2, 50.0);
  EXPECT_FALSE(f.edge.has_value());

  // The same error after 50 m of travel (std 1.5 m, 15 deg) is plausible drift: accepted.
  const Revisit longer(CPose2D(1.2, 0.9, 12 * kDeg), 50.0, 13);
  EXPECT_EQ(verifyLoop(longer.graph, longer.old_node, longer.new_node, LoopClosureParams(),
                       plicp::PlicpParams()).verdict,
            Verdict::Accepted);
}

TEST(VerifyLoop, AGuessTooFarForPlicpIsFoundByTheCorrelativeSearch)
{
  // 2.7 m and 50 deg off after 150 m of travel (drift std 4.5 m, 45 deg): PLICP from the
  // graph's guess does not get there; the search around it (3 std, capped by the window) does.
  const Revisit r(CPose2D(2.2, -1.6, 50 * kDeg), 150.0, 14);
  const LoopCheck plain = verifyLoop(r.graph, r.old_node, r.new_node, LoopClosureParams(), plicp::PlicpParams());
  EXPECT_NE(plain.verdict, Verdict::Accepted) << toString(plain.verdict);
  EXPECT_FALSE(plain.searched);
  const LoopCheck c = verifyLoop(r.graph, r.old_node, r.new_node, LoopClosureParams(), plicp::PlicpParams(),
                                 correlative::CorrelativeParams());
  ASSERT_EQ(c.verdict, Verdict::Accepted) << toString(c.verdict) << " " << c.match.message;
  EXPECT_TRUE(c.searched);
  EXPECT_NEAR(c.edge->z.x(), r.truth().x(), 0.03);
  EXPECT_NEAR(c.edge->z.y(), r.truth().y(), 0.03);
  EXPECT_NEAR(c.edge->z.phi(), r.truth().phi(), 0.01);

  // A disabled search is no search.
  correlative::CorrelativeParams off;
  off.enabled = false;
  EXPECT_EQ(verifyLoop(r.graph, r.old_node, r.new_node, LoopClosureParams(), plicp::PlicpParams(), off).verdict,
            plain.verdict);
}

TEST(VerifyLoop, AnAmbiguousSearchInAPeriodicCorridorGivesNoLoop)
{
  // A corridor with a pillar pair every metre, seen all round to 20 m: a shift by a metre looks
  // the same but for the ends of the view (and the motion prior's cost). The graph's guess is
  // 1.2 m and 40 deg off, so PLICP alone fails and the search decides.
  test::World world;
  world.segments = {{-40, -1.5, 40, -1.5}, {-40, 1.5, 40, 1.5}};
  for (int k = -40; k <= 40; k++)
  {
    world.circles.push_back({1.0 * k, -1.0, 0.15});
    world.circles.push_back({1.0 * k, 1.0, 0.15});
  }
  std::mt19937 rng(15);
  auto node = [&](size_t id, const CPose2D& pose, double path) {
    auto obs = test::simulateObservation(world, pose, 720, 2 * M_PI - 0.01, 20, 0.01, rng);
    return LoopNode{id, std::make_shared<const plicp::ReferenceScan>(sensor::scanFromObservation(obs)), path};
  };
  const CPose2D a(0, 0, 0), b(0.5, 0.1, 0.2);
  graph::PoseGraph graph;
  graph.addNode(0, a);
  graph.addNode(40, b + CPose2D(1.2, 0.3, 40 * kDeg));
  const LoopNode old_node = node(0, a, 0), new_node = node(40, b, 150);
  LoopClosureParams p;
  p.ambiguity_margin = 0.1;
  const LoopCheck c = verifyLoop(graph, old_node, new_node, p, plicp::PlicpParams(), correlative::CorrelativeParams());
  EXPECT_NE(c.verdict, Verdict::Accepted) << toString(c.verdict);
  EXPECT_FALSE(c.searched);
  // Without the ambiguity check the search does pick one of the look-alike poses.
  LoopClosureParams no_check = p;
  no_check.ambiguity_radius = 0;
  const LoopCheck d = verifyLoop(graph, old_node, new_node, no_check, plicp::PlicpParams(), correlative::CorrelativeParams());
  EXPECT_TRUE(d.searched);
}

TEST(VerifyLoop, AWrongPlaceIsNotAccepted)
{
  // The graph believes node 40 is next to node 0, but its scan was taken 15 m away. (With
  // this seed PLICP moves beyond max_correction_xy from the guess: MatchFailed.)
  const test::World world = test::clutteredWorld(5);
  std::mt19937 rng(14);
  const CPose2D a(-10, -3, 0.1);
  const LoopNode old_node = nodeAt(world, 0, a, 0.0, rng);
  const LoopNode new_node = nodeAt(world, 40, CPose2D(5, -3.5, 0.1), 30.0, rng);
  graph::PoseGraph g;
  g.addNode(0, a);
  g.addNode(40, a + CPose2D(0.6, 0.2, 3 * kDeg));
  const LoopCheck c = verifyLoop(g, old_node, new_node, LoopClosureParams(), plicp::PlicpParams());
  EXPECT_NE(c.verdict, Verdict::Accepted) << "d2 " << c.mahalanobis2 << " inliers "
                                          << c.inlier_fraction;
  EXPECT_FALSE(c.edge.has_value());
}

TEST(VerifyLoop, AScanWithoutValidRaysFailsTheMatchCleanly)
{
  Revisit r(CPose2D(0.4, -0.3, 5 * kDeg), 20.0, 15);
  sensor::Scan blind = r.new_node.scan->scan;
  blind.angles.clear();
  blind.ranges.clear();
  blind.points.clear();
  blind.beam_index.clear();
  r.new_node.scan = std::make_shared<const plicp::ReferenceScan>(blind);
  const LoopCheck c = verifyLoop(r.graph, r.old_node, r.new_node, LoopClosureParams(), plicp::PlicpParams());
  EXPECT_EQ(c.verdict, Verdict::MatchFailed);
  EXPECT_EQ(c.match.status, plicp::MatchStatus::TooFewCorrespondences);
  EXPECT_FALSE(c.edge.has_value());
  EXPECT_TRUE(std::isinf(c.mahalanobis2));
}

TEST(VerifyLoop, BadInputsAreErrorsOrFailedMatches)
{
  Revisit r(CPose2D(), 20.0, 16);
  const LoopClosureParams p;
  const plicp::PlicpParams pp;
  LoopNode missing = r.new_node;
  missing.id = 7;
  EXPECT_THROW(verifyLoop(r.graph, r.old_node, missing, p, pp), std::invalid_argument);
  EXPECT_THROW(verifyLoop(r.graph, r.old_node, r.old_node, p, pp), std::invalid_argument);
  LoopNode no_scan = r.new_node;
  no_scan.scan.reset();
  EXPECT_THROW(verifyLoop(r.graph, r.old_node, no_scan, p, pp), std::invalid_argument);
  // A scan from another mounting cannot be matched: a failed match, not a wrong edge.
  std::mt19937 rng(17);
  const LoopNode other = nodeAt(r.world, 40, r.b, 20.0, rng, CPose2D());
  const LoopCheck c = verifyLoop(r.graph, r.old_node, other, p, pp);
  EXPECT_EQ(c.verdict, Verdict::MatchFailed);
  EXPECT_EQ(c.match.status, plicp::MatchStatus::InvalidInput);
}

TEST(CheckLoops, VerifiesOnlyTheCandidates)
{
  const Revisit r(CPose2D(0.4, -0.3, 5 * kDeg), 20.0, 18);
  graph::PoseGraph g = r.graph;
  for (size_t k = 1; k < 40; k++) g.addNode(k, CPose2D(20.0 + k, 20.0, 0));  // far away
  std::vector<size_t> asked;
  const auto checks = checkLoops(g, r.new_node, [&](size_t id) {
    asked.push_back(id);
    return r.old_node;
  }, nullptr, LoopClosureParams(), plicp::PlicpParams());
  EXPECT_EQ(asked, (std::vector<size_t>{0}));
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_EQ(checks[0].verdict, Verdict::Accepted);
}

TEST(LoopGate, MahalanobisMatchesAHandComputedValue)
{
  // predicted (1, 2, 90 deg), measured 0.3 m further along map y and 0.1 rad more: in the
  // predicted frame e = (0.3, 0, 0.1). The measured covariance diag(0.01, 0.04, 0.0025)
  // (old node's frame) turns by 90 deg into diag(0.04, 0.01, 0.0025); the drift after 2 m at
  // 0.05 m/m and 0.025 rad/m adds diag(0.01, 0.01, 0.0025): d2 = 0.09/0.05 + 0.01/0.005 = 3.8.
  LoopClosureParams p;
  p.drift_xy_per_m = 0.05;
  p.drift_theta_per_m = 0.025;
  p.min_drift_sigma_xy = 0.01;
  p.min_drift_sigma_theta = 0.001;
  const Eigen::Matrix3d drift = driftCovariance(2.0, p);
  EXPECT_LT((drift - Eigen::Vector3d(0.01, 0.01, 0.0025).asDiagonal().toDenseMatrix()).norm(), 1e-15);
  const Eigen::Matrix3d cov = Eigen::Vector3d(0.01, 0.04, 0.0025).asDiagonal();
  const CPose2D predicted(1, 2, M_PI / 2), measured(1, 2.3, M_PI / 2 + 0.1);
  EXPECT_NEAR(loopMahalanobis2(predicted, measured, cov, drift), 3.8, 1e-12);
  // Angles wrap: -179 deg against 179 deg is 2 deg apart.
  const Eigen::Matrix3d unit = Eigen::Matrix3d::Identity();
  EXPECT_NEAR(loopMahalanobis2(CPose2D(0, 0, 179 * kDeg), CPose2D(0, 0, -179 * kDeg), unit, 0 * unit),
              std::pow(2 * kDeg, 2), 1e-12);
  EXPECT_TRUE(std::isinf(loopMahalanobis2(predicted, measured, 0 * unit, 0 * unit)));
}

TEST(LoopGate, DriftGrowsWithTravelAboveItsFloor)
{
  const LoopClosureParams p;  // 0.03 m/m, 0.3 deg/m, floors 0.1 m and 1 deg
  EXPECT_NEAR(driftCovariance(0.0, p)(0, 0), 0.01, 1e-15);
  EXPECT_NEAR(driftCovariance(0.0, p)(2, 2), std::pow(1 * kDeg, 2), 1e-15);
  EXPECT_NEAR(driftCovariance(100.0, p)(1, 1), 9.0, 1e-12);
  EXPECT_NEAR(driftCovariance(-100.0, p)(2, 2), std::pow(30 * kDeg, 2), 1e-12);
  EXPECT_EQ(driftCovariance(100.0, p)(0, 1), 0.0);
}

TEST(LoopClosureParams, LoadsSavesAndRejectsBadValuesAndKeys)
{
  mrpt::config::CConfigFileMemory ini;
  ini.write("loop_closure", "min_index_gap", 12);
  ini.write("loop_closure", "drift_theta_per_m_DEG", 0.5);
  ini.write("loop_closure", "enabled", false);
  const auto p = LoopClosureParams::table().load(ini);
  EXPECT_EQ(p.min_index_gap, 12);
  EXPECT_FALSE(p.enabled);
  EXPECT_NEAR(p.drift_theta_per_m, 0.5 * kDeg, 1e-12);
  mrpt::config::CConfigFileMemory saved;
  LoopClosureParams::table().save(p, saved);
  const mrpt::config::CConfigFileMemory reread(saved.getContent());  // as a file would be
  const auto q = LoopClosureParams::table().load(reread);
  EXPECT_EQ(q.min_index_gap, 12);
  EXPECT_NEAR(q.drift_theta_per_m, p.drift_theta_per_m, 1e-9);
  EXPECT_NEAR(q.min_drift_sigma_theta, p.min_drift_sigma_theta, 1e-9);

  mrpt::config::CConfigFileMemory typo;
  typo.write("loop_closure", "max_distanse", 3.0);
  EXPECT_THROW(LoopClosureParams::table().load(typo), std::invalid_argument);
  mrpt::config::CConfigFileMemory bad;
  bad.write("loop_closure", "chi2_gate", -1.0);
  EXPECT_THROW(LoopClosureParams::table().load(bad), std::invalid_argument);
  mrpt::config::CConfigFileMemory window;
  window.write("loop_closure", "consistency_window", 4);
  EXPECT_EQ(LoopClosureParams::table().load(window).consistency_window, 4);
  window.write("loop_closure", "ambiguity_radius", 1.5);
  EXPECT_EQ(LoopClosureParams::table().load(window).ambiguity_radius, 1.5);
  window.write("loop_closure", "consistency_window", -1);
  EXPECT_THROW(LoopClosureParams::table().load(window), std::invalid_argument);
}
