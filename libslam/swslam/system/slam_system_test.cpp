// The whole system: deterministic repeatability, threaded tracking, loop closure, bad input.
#include <swslam/eval/report.h>
#include <swslam/io/scan_source.h>
#include <swslam/map/builder.h>
#include <swslam/system/slam_system.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "test_support.h"

using namespace swslam;
using namespace swslam::system;
using mrpt::poses::CPose2D;

namespace
{
const std::string kLake = std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short";

SystemParams defaultParams() { return loadSystemParams(std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini"); }

/** Feeds the first `n` scans of lake-short. */
void feedLake(SlamSystem& slam, size_t n)
{
  auto src = io::openScanSource(kLake + ".rawlog", io::ScanSourceOptions{}, io::CarmenParams());
  sensor::ScanInput in;
  for (size_t i = 0; i < n && src->next(in); i++) ASSERT_TRUE(slam.feed(in).ok());
}

double ate(const RunResults& r)
{
  return eval::evaluateTrajectory(r.trajectory, common::readTum(kLake + ".gt.tum"), 0.01).ate.position.rmse;
}

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const test::World& world, const CPose2D& pose,
                                               double t, std::mt19937& rng)
{
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>(
      test::simulateObservation(world, pose, 541, 1.5 * M_PI, 30, 0.01, rng));
  obs->timestamp = mrpt::Clock::fromDouble(t);
  return obs;
}

/** Drives a 7 m radius circle on the water between the two banks of a cluttered scene, a bit
 * more than once round, deterministically; `truth` gets the true poses. */
RunResults runCircuit(const SystemParams& p, std::vector<common::StampedPose>& truth, int laps = 1)
{
  SlamSystem slam(p, RunMode::Deterministic);
  test::World world = test::clutteredWorld(7);
  std::mt19937 rng(8);
  const double r = 7, speed = 1.5, dt = 0.05;
  const int n = static_cast<int>(laps * 2 * M_PI * r / (speed * dt)) + 40;
  for (int k = 0; k < n; k++)
  {
    const double a = speed * dt * k / r;
    const CPose2D pose(r * std::sin(a), -10 + r - r * std::cos(a), a);
    truth.push_back({dt * k, pose});
    EXPECT_TRUE(slam.feed({scanAt(world, pose, dt * k, rng), {}}).ok());
  }
  slam.finish();
  return slam.results();
}

/** The two runs' trajectories, graphs and maps are bit-identical. */
void expectSameRun(const RunResults& a, const mrpt::maps::COccupancyGridMap2D& map_a,
                   const RunResults& b, const mrpt::maps::COccupancyGridMap2D& map_b)
{
  ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
  for (size_t i = 0; i < a.trajectory.size(); i++)
  {
    ASSERT_EQ(a.trajectory[i].pose.x(), b.trajectory[i].pose.x()) << i;
    ASSERT_EQ(a.trajectory[i].pose.y(), b.trajectory[i].pose.y()) << i;
    ASSERT_EQ(a.trajectory[i].pose.phi(), b.trajectory[i].pose.phi()) << i;
  }
  EXPECT_EQ(a.graph.edgeCount(), b.graph.edgeCount());
  EXPECT_EQ(a.loops, b.loops);
  ASSERT_EQ(map_a.getSizeX(), map_b.getSizeX());
  ASSERT_EQ(map_a.getSizeY(), map_b.getSizeY());
  EXPECT_EQ(map_a.getRawMap(), map_b.getRawMap());
}
}  // namespace

TEST(SlamSystem, DeterministicRunsAreBitIdentical)
{
  RunResults a, b;
  mrpt::maps::COccupancyGridMap2D map_a, map_b;
  for (auto* out : {&a, &b})
  {
    SlamSystem slam(defaultParams(), RunMode::Deterministic);
    feedLake(slam, 800);
    slam.finish();
    *out = slam.results();
    (out == &a ? map_a : map_b) = slam.mapSnapshot();
  }
  ASSERT_EQ(a.trajectory.size(), 800u);
  expectSameRun(a, map_a, b, map_b);
  EXPECT_LT(ate(a), 0.1);
}

TEST(SlamSystem, ThreadedRunTracksTheLogAndFillsEveryStat)
{
  SlamSystem slam(defaultParams(), RunMode::Threaded);
  feedLake(slam, 800);
  slam.finish();
  EXPECT_EQ(slam.error(), "");
  const RunResults r = slam.results();
  ASSERT_EQ(r.trajectory.size(), 800u);
  ASSERT_EQ(r.stats.size(), 800u);
  EXPECT_LT(ate(r), 0.1);
  size_t nodes = 0, graph_runs = 0, map_runs = 0;
  for (const ScanStats& s : r.stats)
  {
    nodes += s.new_node;
    graph_runs += s.graph_ms > 0;
    map_runs += s.map_ms > 0;
  }
  EXPECT_EQ(nodes, r.graph.nodeCount());
  EXPECT_GE(graph_runs, nodes - 1);  // every node but the first is optimized
  EXPECT_GT(map_runs, 0u);
  EXPECT_EQ(r.keyframes.size(), r.graph.nodeCount());
  EXPECT_GT(slam.mapSnapshot().getSizeX(), 0u);
}

TEST(SlamSystem, ThreadedRunWithoutGraphLagEqualsTheDeterministicRun)
{
  // max_graph_lag = 0: tracking takes each scan after the graph has optimized every keyframe
  // sent, as deterministic mode does, so the three threads give the very same result.
  SystemParams p = defaultParams();
  ASSERT_EQ(p.system.max_graph_lag, 0);  // the default
  // A slower graph thread (the whole graph in the window at every node), so that tracking would
  // run ahead of it: with max_graph_lag = -1 the trajectories then differ.
  p.graph_optimizer.window_size = 100000;
  RunResults det, thr;
  mrpt::maps::COccupancyGridMap2D map_det, map_thr;
  for (const RunMode mode : {RunMode::Deterministic, RunMode::Threaded})
  {
    SlamSystem slam(p, mode);
    feedLake(slam, 2461);
    slam.finish();
    EXPECT_EQ(slam.error(), "");
    (mode == RunMode::Threaded ? thr : det) = slam.results();
    (mode == RunMode::Threaded ? map_thr : map_det) = slam.mapSnapshot();
  }
  ASSERT_EQ(thr.trajectory.size(), 2461u);
  expectSameRun(det, map_det, thr, map_thr);
}

TEST(SlamSystem, AStampThatJumpedForwardDoesNotEndTheRun)
{
  test::World world = test::roomWorld();
  for (int resume : {5, 0})
  {
    SystemParams p = defaultParams();
    p.system.timestamp_resume_scans = resume;
    SlamSystem slam(p, RunMode::Deterministic);
    std::mt19937 rng(3);
    double x = 0;
    auto feedAt = [&](double t) { return slam.feed({scanAt(world, CPose2D(x += 0.05, 0, 0), t, rng), {}}); };
    ASSERT_TRUE(feedAt(10.0).ok());
    ASSERT_TRUE(feedAt(10.1).ok());
    ASSERT_TRUE(feedAt(1000.0).ok());  // a corrupt stamp, taken (nothing says it yet)
    // Behind it but out of order among themselves: no resumption.
    EXPECT_EQ(feedAt(10.3).status, FeedStatus::TimestampNotIncreasing);
    EXPECT_EQ(feedAt(10.25).status, FeedStatus::TimestampNotIncreasing);
    for (int k = 0; k < 3; k++) EXPECT_EQ(feedAt(10.4 + 0.1 * k).status, FeedStatus::TimestampNotIncreasing) << k;
    const FeedResult fifth = feedAt(10.7);  // the 5th in order (10.25 started the run)
    if (resume == 0)
    {
      EXPECT_EQ(fifth.status, FeedStatus::TimestampNotIncreasing);
      EXPECT_EQ(feedAt(10.8).status, FeedStatus::TimestampNotIncreasing);
      continue;
    }
    EXPECT_EQ(fifth.status, FeedStatus::TimestampsResumed);
    EXPECT_TRUE(fifth.ok());
    EXPECT_NE(fifth.message.find("jumped forward"), std::string::npos) << fifth.message;
    EXPECT_EQ(feedAt(10.8).status, FeedStatus::Accepted);
    slam.finish();
    EXPECT_EQ(slam.results().trajectory.size(), 5u);  // 10.0, 10.1, 1000, 10.7, 10.8
    EXPECT_EQ(slam.error(), "");
  }
}

TEST(SlamSystem, AScanStampedOutside1970To2200IsSkippedWithAReason)
{
  SlamSystem slam(defaultParams(), RunMode::Deterministic);
  test::World world = test::roomWorld();
  std::mt19937 rng(3);
  ASSERT_TRUE(slam.feed({scanAt(world, CPose2D(0, 0, 0), 1.7e9, rng), {}}).ok());
  // Milliseconds; and -1 s, which MRPT's clock wraps to 1.8e12 s.
  for (double t : {1.7e12, -1.0})
  {
    const FeedResult r = slam.feed({scanAt(world, CPose2D(0.05, 0, 0), t, rng), {}});
    EXPECT_EQ(r.status, FeedStatus::TimestampOutOfRange) << t;
    EXPECT_NE(r.message.find("is outside 1970-2200"), std::string::npos) << r.message;
  }
  EXPECT_EQ(slam.feed({scanAt(world, CPose2D(0.05, 0, 0), 1.7e12, rng), {}}).message,
            "timestamp 1.7e+12 s is outside 1970-2200 (milliseconds rather than seconds?)");
  // The scans after it are judged against the last good one.
  EXPECT_TRUE(slam.feed({scanAt(world, CPose2D(0.1, 0, 0), 1.7e9 + 0.1, rng), {}}).ok());
  EXPECT_EQ(slam.status().skipped, 3u);
}

TEST(SlamSystem, RepeatedStampsAreTakenAndBackwardOrMalformedScansSkippedWithAReason)
{
  SlamSystem slam(defaultParams(), RunMode::Deterministic);
  test::World world = test::roomWorld();
  std::mt19937 rng(3);
  ASSERT_TRUE(slam.feed({scanAt(world, CPose2D(0, 0, 0), 9.9, rng), {}}).ok());
  ASSERT_TRUE(slam.feed({scanAt(world, CPose2D(0, 0, 0), 10.0, rng), {}}).ok());
  const FeedResult dup = slam.feed({scanAt(world, CPose2D(0, 0, 0), 10.0, rng), {}});
  EXPECT_EQ(dup.status, FeedStatus::TimestampStepBack);  // a logger's repeated stamp: taken
  EXPECT_NE(dup.message.find("equal"), std::string::npos) << dup.message;
  const FeedResult back = slam.feed({scanAt(world, CPose2D(0, 0, 0), 8.5, rng), {}});
  EXPECT_EQ(back.status, FeedStatus::TimestampNotIncreasing);  // beyond timestamp_step_back (1 s)
  EXPECT_NE(back.message.find("before"), std::string::npos) << back.message;
  auto bad = scanAt(world, CPose2D(0, 0, 0), 11.0, rng);
  bad->aperture = 0;
  EXPECT_EQ(slam.feed({bad, {}}).status, FeedStatus::BadGeometry);
  EXPECT_EQ(slam.feed({nullptr, {}}).status, FeedStatus::BadGeometry);
  ASSERT_TRUE(slam.feed({scanAt(world, CPose2D(0.1, 0, 0), 11.0, rng), {}}).ok());
  slam.finish();
  EXPECT_EQ(slam.status().skipped, 3u);
  EXPECT_EQ(slam.results().trajectory.size(), 4u);
  EXPECT_EQ(slam.results().trajectory[2].t, 10.0);  // under its own stamp
  EXPECT_EQ(slam.feed({scanAt(world, CPose2D(0.2, 0, 0), 12.0, rng), {}}).status, FeedStatus::Stopped);
}

TEST(SlamSystem, OpenWaterIsTrackedThroughWithoutAJump)
{
  // 1 m/s along x at 20 Hz; from scan 40 to 100 no ray returns (open water), with odometry.
  SlamSystem slam(defaultParams(), RunMode::Deterministic);
  test::World world = test::clutteredWorld(5);
  std::mt19937 rng(4);
  for (int k = 0; k < 140; k++)
  {
    const CPose2D pose(-10 + 0.05 * k, 0, 0);
    auto obs = scanAt(world, pose, 0.05 * k, rng);
    if (k >= 40 && k < 100)
      for (size_t i = 0; i < obs->getScanSize(); i++) obs->setScanRangeValidity(i, false);
    ASSERT_TRUE(slam.feed({obs, k > 0 ? std::optional<CPose2D>(CPose2D(0.05, 0, 0)) : std::nullopt}).ok());
  }
  slam.finish();
  const RunResults r = slam.results();
  size_t fallback = 0;
  for (const ScanStats& s : r.stats) fallback += s.source == tracking::TrackingSource::Odometry;
  EXPECT_GE(fallback, 60u);
  for (size_t k = 0; k < r.trajectory.size(); k++)
    EXPECT_NEAR(r.trajectory[k].pose.x(), 0.05 * k, 0.3) << k;  // the map frame is the first pose
  bool prior = false;
  for (size_t i = 0; i < r.graph.edgeCount(); i++) prior |= r.graph.edge(i).kind == graph::EdgeKind::OdometryPrior;
  EXPECT_TRUE(prior);
}

TEST(SlamSystem, ClosesALoopAroundACircuit)
{
  // A 7 m radius circle on the water between the two banks of a cluttered scene: returning
  // to the start must add verified loop edges, and the trajectory stays on the circle. The
  // online loops only: every loop edge is one the loop closer counted (the final refinement's
  // loop edges are tested below).
  SystemParams p = defaultParams();
  p.final_refinement.enabled = false;
  p.graph_optimizer.max_nodes_per_area = 0;  // every loop stays an edge (merging: below)
  // Every loop asks for a full optimization (the paper's rule; the default asks only for
  // those that disagree with the graph, see LoopsThatAgreeWithTheGraphAreLeftToTheWindow).
  p.graph_optimizer.full_optimization_loop_xy = 0;
  p.graph_optimizer.full_optimization_loop_theta = 0;
  std::vector<common::StampedPose> truth;
  const RunResults res = runCircuit(p, truth);
  EXPECT_GT(res.loops, 0u);
  size_t loop_edges = 0;
  for (size_t i = 0; i < res.graph.edgeCount(); i++) loop_edges += res.graph.edge(i).kind == graph::EdgeKind::Loop;
  EXPECT_EQ(loop_edges, res.loops);
  EXPECT_LT(eval::evaluateTrajectory(res.trajectory, truth, 0.001).ate.position.rmse, 0.1);

  // Loops come node after node here: full optimizations at least full_optimization_interval
  // nodes apart (but for the final one, on the last row), and one within that many nodes of
  // every loop.
  const size_t interval = p.graph_optimizer.full_optimization_interval;
  ASSERT_GT(interval, 1u);
  std::vector<size_t> loop_nodes, full_nodes;
  size_t node = 0, nodes = 0;
  for (const ScanStats& row : res.stats)
  {
    if (row.new_node) node = nodes++;  // node ids count up from 0
    if (row.loops > 0) loop_nodes.push_back(node);
    if (row.full_optimization) full_nodes.push_back(node);
  }
  ASSERT_GT(loop_nodes.size(), 1u);
  ASSERT_FALSE(full_nodes.empty());
  EXPECT_LT(full_nodes.size(), loop_nodes.size());
  for (size_t k = 1; k + 1 < full_nodes.size(); ++k)
    EXPECT_GE(full_nodes[k] - full_nodes[k - 1], interval);
  for (const size_t l : loop_nodes)
    EXPECT_TRUE(std::any_of(full_nodes.begin(), full_nodes.end(),
                            [&](size_t f) { return f >= l && f <= l + interval; }))
        << "loop at node " << l;
}

namespace
{
/** Full optimizations during the run: all but the last row's (the end of the run). */
size_t fullOptimizationsDuringRun(const RunResults& r)
{
  if (r.stats.empty()) return 0;
  return static_cast<size_t>(std::count_if(r.stats.begin(), r.stats.end() - 1,
                                           [](const ScanStats& s) { return s.full_optimization; }));
}

/** The circuit without the final refinement, loops asking for a full optimization past
 * (xy, theta). */
RunResults circuitWithLoopThresholds(double xy, double theta, std::vector<common::StampedPose>& truth)
{
  SystemParams p = defaultParams();
  p.final_refinement.enabled = false;
  p.graph_optimizer.full_optimization_loop_xy = xy;
  p.graph_optimizer.full_optimization_loop_theta = theta;
  p.graph_optimizer.max_nodes_per_area = 0;  // the same candidates whatever the thresholds
  return runCircuit(p, truth);
}
}  // namespace

TEST(SlamSystem, RevisitsAreMergedIntoTheNodesOfTheFirstLap)
{
  // The circuit driven three times: the later laps' keyframes that a loop ties to the first
  // lap's nodes are merged into them, so the graph keeps about one lap's nodes, and the
  // trajectory is as good as with every node kept.
  SystemParams p = defaultParams();
  ASSERT_GT(p.graph_optimizer.max_nodes_per_area, 0u);
  std::vector<common::StampedPose> truth1, truth3, truth_kept;
  const RunResults one = runCircuit(p, truth1, 1);
  const RunResults three = runCircuit(p, truth3, 3);
  SystemParams keep = p;
  keep.graph_optimizer.max_nodes_per_area = 0;
  const RunResults kept = runCircuit(keep, truth_kept, 3);
  EXPECT_TRUE(kept.graph.merged().empty());
  EXPECT_GT(three.graph.merged().size(), three.graph.liveNodeCount());
  EXPECT_LT(three.graph.liveNodeCount(), 1.3 * one.graph.liveNodeCount());
  EXPECT_EQ(three.graph.nodeCount(), kept.graph.nodeCount());
  // Merged as they leave the sliding window, their scans leave the map again.
  EXPECT_LT(three.map_bytes, 1.3 * one.map_bytes) << "kept: " << kept.map_bytes;
  for (size_t k = 0; k < three.graph.edgeCount(); ++k)
    EXPECT_FALSE(three.graph.isMerged(three.graph.edge(k).from) || three.graph.isMerged(three.graph.edge(k).to));
  const double ate3 = eval::evaluateTrajectory(three.trajectory, truth3, 0.001).ate.position.rmse;
  const double ate_kept = eval::evaluateTrajectory(kept.trajectory, truth_kept, 0.001).ate.position.rmse;
  EXPECT_LT(ate3, 0.1);
  EXPECT_LT(ate3, ate_kept + 0.02);
}

TEST(SlamSystem, LoopsThatAgreeWithTheGraphAreLeftToTheWindow)
{
  // Around the circuit the loops agree with the graph within millimetres. Every loop asks for
  // a full optimization under the paper's rule (0, 0) and past a 0.01 mm threshold; none
  // past 1 km; with the default thresholds fewer than under the paper's rule. The loops
  // found are the same, and the trajectory as good.
  std::vector<common::StampedPose> truth;
  const RunResults every = circuitWithLoopThresholds(0, 0, truth);
  const RunResults tiny = circuitWithLoopThresholds(1e-5, 1e-5, truth);
  const RunResults never = circuitWithLoopThresholds(1e3, M_PI, truth);
  const SystemParams d = defaultParams();
  ASSERT_GT(d.graph_optimizer.full_optimization_loop_xy, 0.0);
  const RunResults deflt = circuitWithLoopThresholds(d.graph_optimizer.full_optimization_loop_xy,
                                                     d.graph_optimizer.full_optimization_loop_theta, truth);
  ASSERT_GT(every.loops, 0u);
  for (const RunResults* r : {&tiny, &never, &deflt}) EXPECT_EQ(r->loops, every.loops);
  EXPECT_GT(fullOptimizationsDuringRun(every), 0u);
  EXPECT_EQ(fullOptimizationsDuringRun(tiny), fullOptimizationsDuringRun(every));
  EXPECT_EQ(fullOptimizationsDuringRun(never), 0u);
  EXPECT_LT(fullOptimizationsDuringRun(deflt), fullOptimizationsDuringRun(every));
  const double ate_every = eval::evaluateTrajectory(every.trajectory, truth, 0.001).ate.position.rmse;
  const double ate_deflt = eval::evaluateTrajectory(deflt.trajectory, truth, 0.001).ate.position.rmse;
  EXPECT_LT(ate_deflt, 0.1);
  EXPECT_NEAR(ate_deflt, ate_every, 0.01);
}

TEST(SlamSystem, FinalRefinementLinksCloseUnlinkedNodesOfTheCircuit)
{
  // On (config/default.ini): the pass adds loop edges between close nodes that shared none,
  // beyond those the loop closer counted, and the circle stays right.
  SystemParams p = defaultParams();
  ASSERT_TRUE(p.final_refinement.enabled);
  // Every node kept: edges carried to the node a revisit merged into may join a pair twice.
  p.graph_optimizer.max_nodes_per_area = 0;
  const auto loopEdges = [](const graph::PoseGraph& g) {
    size_t n = 0;
    for (size_t i = 0; i < g.edgeCount(); i++) n += g.edge(i).kind == graph::EdgeKind::Loop;
    return n;
  };
  std::vector<common::StampedPose> truth;
  const RunResults res = runCircuit(p, truth);
  std::set<std::pair<size_t, size_t>> pairs;
  for (size_t i = 0; i < res.graph.edgeCount(); i++)
  {
    const auto& e = res.graph.edge(i);
    EXPECT_TRUE(pairs.insert({std::min(e.from, e.to), std::max(e.from, e.to)}).second)
        << "pair " << e.from << "-" << e.to << " linked twice";
  }
  EXPECT_GT(res.loops, 0u);
  EXPECT_GT(loopEdges(res.graph), res.loops);
  EXPECT_LT(eval::evaluateTrajectory(res.trajectory, truth, 0.001).ate.position.rmse, 0.1);
  // Loop edges, the loop closer's and the refinement's (radius 3 m < max_distance), join no
  // nodes farther apart than the loop closer's max_distance (with some slack for the
  // optimization that followed).
  for (size_t i = 0; i < res.graph.edgeCount(); i++)
  {
    const auto& e = res.graph.edge(i);
    if (e.kind != graph::EdgeKind::Loop) continue;
    const double d = (res.graph.pose(e.from).translation() - res.graph.pose(e.to).translation()).norm();
    EXPECT_LT(d, p.loop_closure.max_distance + 0.5);
  }
}

namespace
{
/** 12 scans 5 cm apart along the room, each with its true odometry but for `bad` (scan index
 * -> increment), which must be dropped with a message holding `why`; the run ends on the true
 * path, every pose finite. */
void odometryIsDroppedWhereItEnters(RunMode mode, const std::map<int, CPose2D>& bad, const std::string& why,
                                    unsigned seed)
{
  SlamSystem slam(defaultParams(), mode);
  test::World world = test::roomWorld();
  std::mt19937 rng(seed);
  for (int k = 0; k < 12; k++)
  {
    const CPose2D pose(0.05 * k, 0, 0);
    const auto it = bad.find(k);
    const std::optional<CPose2D> odometry = it == bad.end() ? CPose2D(0.05, 0, 0) : it->second;
    const FeedResult r = slam.feed({scanAt(world, pose, 10.0 + 0.1 * k, rng), odometry});
    EXPECT_TRUE(r.ok()) << r.message;
    if (it != bad.end())
    {
      EXPECT_EQ(r.status, FeedStatus::OdometryDropped);
      EXPECT_NE(r.message.find(why), std::string::npos) << r.message;
    }
    else
      EXPECT_EQ(r.status, FeedStatus::Accepted) << r.message;
  }
  slam.finish();
  EXPECT_EQ(slam.error(), "");
  const RunResults res = slam.results();
  ASSERT_EQ(res.trajectory.size(), 12u);
  for (const common::StampedPose& p : res.trajectory)
    ASSERT_TRUE(std::isfinite(p.pose.x()) && std::isfinite(p.pose.y()) && std::isfinite(p.pose.phi()))
        << "t " << p.t;
  EXPECT_NEAR(res.trajectory.back().pose.x(), 0.55, 0.05);
  EXPECT_NEAR(res.trajectory.back().pose.y(), 0, 0.05);
}
}  // namespace

TEST(SlamSystem, AnOdometryIncrementThatIsNotFiniteIsDroppedNotPropagated)
{
  // One NaN odometry reading in a rawlog made every later pose NaN, with a clean exit.
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const RunMode mode : {RunMode::Deterministic, RunMode::Threaded})
    odometryIsDroppedWhereItEnters(mode, {{5, CPose2D(nan, 0, 0)}, {6, CPose2D(0.05, 0, inf)}}, "not finite", 4);
}

TEST(SlamSystem, AnOdometryIncrementNoVehicleReachesIsDroppedWhereItEnters)
{
  // One odometry value of -5.3e25 in a good rawlog grew the search past 12 GB; 60 m in 0.1 s.
  odometryIsDroppedWhereItEnters(RunMode::Deterministic, {{5, CPose2D(-5.3e25, 0, 0)}, {7, CPose2D(0, 60, 0)}},
                                 "beyond [system] max_odometry_speed (50 m/s)", 6);
}

TEST(SlamSystem, AModuleThatFailsInDeterministicModeStopsThePipelineAsInThreadedMode)
{
  // An odometry jump of 1000 km: tracking falls back to it, the map refuses the node. The
  // failure is the map's (not an exception out of feed()), and what came before is kept.
  auto params = defaultParams();
  params.system.max_odometry_speed = 0;  // no check: let the jump reach the modules
  params.tracking.unmatched_scans_skipped = 0;  // the unmatched scan is a node at once
  SlamSystem slam(params, RunMode::Deterministic);
  test::World world = test::roomWorld();
  std::mt19937 rng(5);
  for (int k = 0; k < 4; k++)
    ASSERT_TRUE(slam.feed({scanAt(world, CPose2D(0.05 * k, 0, 0), 10.0 + 0.1 * k, rng), CPose2D(0.05, 0, 0)}).ok());
  FeedResult jump;
  EXPECT_NO_THROW(jump = slam.feed({scanAt(world, CPose2D(0.2, 0, 0), 10.4, rng), CPose2D(1e6, 0, 0)}));
  EXPECT_NE(slam.error().find("map construction: "), std::string::npos) << slam.error();
  EXPECT_NE(slam.error().find("bad odometry"), std::string::npos) << slam.error();
  EXPECT_EQ(slam.feed({scanAt(world, CPose2D(0.2, 0, 0), 10.5, rng), {}}).status, FeedStatus::Stopped);
  EXPECT_NO_THROW(slam.finish());
  const RunResults res = slam.results();
  EXPECT_EQ(res.trajectory.size(), 5u);
  EXPECT_GE(res.graph.nodeCount(), 1u);
}

TEST(SlamSystem, AResumedSessionMapsItsNodesAtTheirPosesAndGoesOnInBothModes)
{
  SlamSystem first(defaultParams(), RunMode::Deterministic);
  feedLake(first, 300);
  first.finish();
  const RunResults saved = first.results();
  // Each node's observation: the lake scan with its stamp.
  ResumedSession session{saved.graph, {}};
  auto src = io::openScanSource(kLake + ".rawlog", io::ScanSourceOptions{}, io::CarmenParams());
  sensor::ScanInput in;
  while (session.observations.size() < saved.keyframes.size() && src->next(in))
    if (std::abs(mrpt::Clock::toDouble(in.observation->timestamp) - saved.keyframes[session.observations.size()].t) < 1e-5)
      session.observations.push_back(in.observation);
  ASSERT_EQ(session.observations.size(), saved.graph.nodeCount());
  // The map a resumed run starts from: every node inserted at its optimized pose.
  map::MapBuilder rebuilt(defaultParams().map);
  for (size_t id = 0; id < session.observations.size(); id++)
    rebuilt.insert(id, *session.observations[id], saved.graph.pose(id));

  for (const RunMode mode : {RunMode::Deterministic, RunMode::Threaded})
  {
    SlamSystem resumed(defaultParams(), mode);
    resumed.resume(session);
    EXPECT_EQ(resumed.mapSnapshot().getRawMap(), rebuilt.snapshot().getRawMap());
    EXPECT_EQ(resumed.mapSnapshot().getSizeX(), rebuilt.snapshot().getSizeX());
    const RunResults before = resumed.results();
    ASSERT_EQ(before.keyframes.size(), saved.keyframes.size());
    for (size_t k = 0; k < saved.keyframes.size(); k++) EXPECT_EQ(before.keyframes[k].t, saved.keyframes[k].t);
    // The scans after the session's: new nodes after its own, no failure.
    auto rest = io::openScanSource(kLake + ".rawlog", io::ScanSourceOptions{}, io::CarmenParams());
    for (size_t i = 0; i < 400 && rest->next(in); i++)
      if (i >= 300) ASSERT_TRUE(resumed.feed(in).ok());
    resumed.finish();
    EXPECT_EQ(resumed.error(), "");
    EXPECT_GT(resumed.results().graph.nodeCount(), saved.graph.nodeCount() + 5);
    EXPECT_THROW(resumed.resume(session), std::logic_error);
  }
  SlamSystem short_of_one(defaultParams(), RunMode::Deterministic);
  ResumedSession missing = session;
  missing.observations.pop_back();
  EXPECT_THROW(short_of_one.resume(missing), std::invalid_argument);
  ResumedSession null_scan = session;
  null_scan.observations[3].reset();
  EXPECT_THROW(short_of_one.resume(null_scan), std::invalid_argument);
}
