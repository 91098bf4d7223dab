// Local tracking on a synthetic cluttered world along a known path.
#include <swslam/tracking/local_tracker.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::tracking;
using mrpt::poses::CPose2D;

namespace
{
/** Vehicle poses along a gentle S-curve at 1.5 m/s sampled at 20 Hz. */
std::vector<CPose2D> sCurve(int n)
{
  std::vector<CPose2D> path;
  for (int k = 0; k < n; k++)
  {
    const double t = 0.05 * k, x = -20 + 1.5 * t, y = -3 + 1.5 * std::sin(0.15 * x);
    const double yaw = std::atan(1.5 * 0.15 * std::cos(0.15 * x));
    path.emplace_back(x, y, yaw);
  }
  return path;
}

/** The scan a sensor mounted at `mount` takes at time t [s]. */
mrpt::obs::CObservation2DRangeScan scanAt(const test::World& world, const CPose2D& vehicle,
                                          const CPose2D& mount, double t, std::mt19937& rng)
{
  auto obs = test::simulateObservation(world, vehicle + mount, 541, 1.5 * M_PI, 30, 0.02, rng);
  obs.sensorPose = mrpt::poses::CPose3D(mount);
  obs.timestamp = mrpt::Clock::fromDouble(1000 + t);
  return obs;
}
}  // namespace

TEST(LocalTracker, FollowsAPathAndMakesKeyframesWithEdges)
{
  // The S-curve with a sensor mounted off the vehicle's centre: every scan's pose and every
  // keyframe edge against the truth.
  const auto world = test::clutteredWorld(5);
  const CPose2D mount(0.3, 0.1, 0.05);
  const auto path = sCurve(300);
  std::mt19937 rng(1);
  LocalTracker tracker(TrackingParams{}, plicp::PlicpParams{});
  std::vector<size_t> scan_of_keyframe;
  size_t consecutive = 0;
  for (size_t k = 0; k < path.size(); k++)
  {
    const auto step = tracker.process(scanAt(world, path[k], mount, 0.05 * k, rng));
    const CPose2D expected = (-path[0]) + path[k];  // the map frame is the first pose
    EXPECT_NEAR(step.pose.x(), expected.x(), 0.1 + 0.002 * k) << "scan " << k;
    EXPECT_NEAR(step.pose.y(), expected.y(), 0.1 + 0.002 * k) << "scan " << k;
    // The first match's prediction is a guess, searched first (tracking::searchFirst()).
    if (k > 0) EXPECT_EQ(step.source, k == 1 ? TrackingSource::Searched : TrackingSource::Match) << step.match.message;
    if (!step.new_keyframe) continue;
    scan_of_keyframe.push_back(k);
    for (const auto& e : step.edges)
    {
      EXPECT_NE(e.kind, graph::EdgeKind::OdometryPrior);
      EXPECT_TRUE(e.information.allFinite());
      // Every edge is the true relative vehicle pose between the two keyframes' scans.
      const CPose2D truth = path[scan_of_keyframe.at(e.to)] - path[scan_of_keyframe.at(e.from)];
      EXPECT_NEAR(e.z.x(), truth.x(), 0.03) << graph::edgeKindName(e.kind) << " " << e.from << "->" << e.to;
      EXPECT_NEAR(e.z.y(), truth.y(), 0.03) << graph::edgeKindName(e.kind) << " " << e.from << "->" << e.to;
      EXPECT_NEAR(e.z.phi(), truth.phi(), 0.01);
      if (e.kind == graph::EdgeKind::Consecutive)
      {
        consecutive++;
        EXPECT_EQ(e.from + 1, e.to);
      }
    }
  }
  const size_t keyframes = scan_of_keyframe.size();
  EXPECT_GT(keyframes, 20u);  // 22 m travelled, a node every 0.5 m
  EXPECT_EQ(consecutive, keyframes - 1);
}

TEST(LocalTracker, DenseEdgesConnectNearbyNodes)
{
  const auto world = test::clutteredWorld(5);
  const auto path = sCurve(200);
  std::mt19937 rng(2);
  TrackingParams tp;
  tp.dense_radius = 2.0;
  LocalTracker tracker(tp, plicp::PlicpParams());
  size_t dense = 0;
  for (size_t k = 0; k < path.size(); k++)
  {
    const auto step = tracker.process(scanAt(world, path[k], CPose2D(), 0.05 * k, rng));
    for (const auto& e : step.edges)
    {
      if (e.kind != graph::EdgeKind::DenseNeighbour) continue;
      dense++;
      const auto& kfs = tracker.keyframes();
      const CPose2D rel = kfs[e.to].pose - kfs[e.from].pose;
      EXPECT_NEAR(e.z.x(), rel.x(), 0.05);
      EXPECT_NEAR(e.z.y(), rel.y(), 0.05);
      EXPECT_LE(rel.norm(), 2.0 + 0.1);
    }
  }
  EXPECT_GT(dense, 10u);  // nodes 0.5 m apart within 2 m: several neighbours each
}

TEST(LocalTracker, ScansWithoutValidRaysFallBackAndSaySo)
{
  const auto world = test::clutteredWorld(5);
  const auto path = sCurve(120);
  std::mt19937 rng(3);
  LocalTracker tracker{TrackingParams(), plicp::PlicpParams()};
  size_t fallbacks = 0, priors = 0;
  for (size_t k = 0; k < path.size(); k++)
  {
    auto obs = scanAt(world, path[k], CPose2D(), 0.05 * k, rng);
    const bool blind = k >= 40 && k < 70;  // 1.5 s of "open water"
    if (blind)
      for (size_t i = 0; i < obs.getScanSize(); i++) obs.setScanRangeValidity(i, false);
    const auto step = tracker.process(obs);
    if (blind)
    {
      EXPECT_EQ(step.source, TrackingSource::ConstantMotion);
      EXPECT_EQ(step.match.status, plicp::MatchStatus::TooFewCorrespondences);
      fallbacks++;
    }
    for (const auto& e : step.edges)
    {
      // Without a match no consecutive edge is made: a weak prior says what happened.
      if (blind) EXPECT_NE(e.kind, graph::EdgeKind::Consecutive);
      if (e.kind == graph::EdgeKind::OdometryPrior)
      {
        priors++;
        EXPECT_LT(e.information(0, 0), 10.0);
      }
    }
    const CPose2D expected = (-path[0]) + path[k];
    EXPECT_NEAR(step.pose.x(), expected.x(), 0.3) << "scan " << k;
  }
  EXPECT_EQ(fallbacks, 30u);
  EXPECT_GE(priors, 1u);
}

TEST(LocalTracker, OdometryIsTheFallbackWhenGiven)
{
  const auto world = test::clutteredWorld(5);
  const auto path = sCurve(60);
  std::mt19937 rng(4);
  LocalTracker tracker{TrackingParams(), plicp::PlicpParams()};
  for (size_t k = 0; k < path.size(); k++)
  {
    auto obs = scanAt(world, path[k], CPose2D(), 0.05 * k, rng);
    if (k == 30)
      for (size_t i = 0; i < obs.getScanSize(); i++) obs.setScanRangeValidity(i, false);
    const auto odo = k > 0 ? std::optional<CPose2D>(path[k] - path[k - 1]) : std::nullopt;
    const auto step = tracker.process(obs, odo);
    EXPECT_EQ(step.source, k == 0 ? TrackingSource::First
                                  : (k == 30 ? TrackingSource::Odometry : TrackingSource::Match));
  }
}

TEST(LocalTracker, MovedKeyframesMoveLaterScans)
{
  const auto world = test::clutteredWorld(5);
  const auto path = sCurve(10);
  std::mt19937 rng(5);
  LocalTracker tracker{TrackingParams(), plicp::PlicpParams()};
  tracker.process(scanAt(world, path[0], CPose2D(), 0.0, rng));
  tracker.setKeyframePose(0, CPose2D(10, 0, 0));
  const auto step = tracker.process(scanAt(world, path[1], CPose2D(), 0.05, rng));
  EXPECT_NEAR(step.pose.x(), 10 + ((-path[0]) + path[1]).x(), 0.02);
}

namespace
{
/** Around an ellipse in the room, 0.5 m per scan, the heading swinging +-30 deg about the
 * tangent from one scan to the next: turns of about 60 deg that alternate, so the last motion
 * predicts the next one badly (as on the subsampled CARMEN logs). */
std::vector<CPose2D> wigglingPath(int n)
{
  std::vector<CPose2D> path;
  for (int k = 0; k < n; k++)
  {
    const double s = 0.1 * k, x = 6 * std::cos(s), y = 3.5 * std::sin(s);
    const double tangent = std::atan2(3.5 * std::cos(s), -6 * std::sin(s));
    path.emplace_back(x, y, tangent + (k % 2 ? 1 : -1) * 30 * M_PI / 180);
  }
  return path;
}

/** Largest position and heading error of a tracked path against the truth (first pose = origin). */
std::pair<double, double> worstError(LocalTracker& tracker, const std::vector<CPose2D>& path,
                                     size_t& searched)
{
  std::mt19937 rng(9);
  const auto world = test::roomWorld();
  double worst_xy = 0, worst_th = 0;
  for (size_t k = 0; k < path.size(); k++)
  {
    auto obs = test::simulateObservation(world, path[k], 181, M_PI, 30, 0.02, rng);
    obs.timestamp = mrpt::Clock::fromDouble(1000 + 0.1 * k);
    const auto step = tracker.process(obs);
    searched += step.source == TrackingSource::Searched;
    const CPose2D truth = (-path[0]) + path[k];
    worst_xy = std::max(worst_xy, (step.pose.translation() - truth.translation()).norm());
    worst_th = std::max(worst_th, std::abs(std::remainder(step.pose.phi() - truth.phi(), 2 * M_PI)));
  }
  return {worst_xy, worst_th};
}
}  // namespace

TEST(LocalTracker, LargeUnpredictedTurnsAreTrackedByTheSearch)
{
  const auto path = wigglingPath(40);
  size_t searched = 0;
  LocalTracker tracker{TrackingParams(), plicp::PlicpParams(), correlative::CorrelativeParams()};
  const auto [xy, th] = worstError(tracker, path, searched);
  EXPECT_LT(xy, 0.15);
  EXPECT_LT(th, 2 * M_PI / 180);
  EXPECT_GT(searched, 10u);  // the turn alternates every scan

  correlative::CorrelativeParams off;
  off.enabled = false;
  size_t none = 0;
  LocalTracker plain(TrackingParams(), plicp::PlicpParams(), off);
  const auto [xy_off, th_off] = worstError(plain, path, none);
  EXPECT_EQ(none, 0u);
  EXPECT_TRUE(xy_off > 0.5 || th_off > 10 * M_PI / 180)
      << "PLICP from the last motion alone should lose this path (" << xy_off << " m, "
      << th_off * 180 / M_PI << " deg)";
}

namespace
{
/** Along a corridor lined with posts every 0.4 m at 2 m/s, scans every 0.05 or 0.15 s in turn
 * (as a loaded computer or a simulator may stamp them): steps of 0.1 and 0.3 m. The last step
 * as the prediction is then 0.2 m off, half the posts' spacing, where PLICP can settle on the
 * wrong post. Returns the worst change of the along-corridor error after the first 10 scans
 * (the first steps, predicted from rest, may start a post off) [m]. */
double corridorDrift(const TrackingParams& tp)
{
  auto world = test::corridorWorld();
  for (double x = -10; x <= 60; x += 0.4) world.circles.push_back({x, 1.0, 0.1});
  std::mt19937 rng(11);
  LocalTracker tracker(tp, plicp::PlicpParams());
  double t = 0, x = 0, worst = 0, start_error = 0;
  for (int k = 0; k < 150; k++)
  {
    auto obs = test::simulateObservation(world, CPose2D(x, 0, 0), 541, 1.5 * M_PI, 8, 0.01, rng);
    obs.timestamp = mrpt::Clock::fromDouble(1000 + t);
    const auto st = tracker.process(obs);
    if (k == 10) start_error = st.pose.x() - x;
    if (k >= 10) worst = std::max(worst, std::abs(st.pose.x() - x - start_error));
    const double dt = k % 2 ? 0.15 : 0.05;
    t += dt;
    x += 2.0 * dt;
  }
  return worst;
}
/** Along a corridor lined with posts every 0.8 m at 3.6 m/s, 18 scans a second, with eight
 * scans dropped every 30 (a 0.43 s gap of 1.55 m, as in the UAL campus log): the last motion
 * scaled by 4 at most is then 0.78 m short, about a post's spacing. Returns the worst change of
 * the along-corridor error from one scan to the next [m] (slow drift aside: a jump). */
double droppedScansJump(const TrackingParams& tp)
{
  auto world = test::corridorWorld();
  for (double x = -10; x <= 100; x += 0.8) world.circles.push_back({x, 1.0, 0.1});
  std::mt19937 rng(13);
  LocalTracker tracker(tp, plicp::PlicpParams());
  const double dt = 1 / 18.0, speed = 3.6;
  double t = 0, worst = 0, last_error = 0;
  for (int k = 0; t * speed < 80; k++)
  {
    const double x = speed * t;
    auto obs = test::simulateObservation(world, CPose2D(x, 0, 0), 541, 1.5 * M_PI, 8, 0.01, rng);
    obs.timestamp = mrpt::Clock::fromDouble(1000 + t);
    const double error = tracker.process(obs).pose.x() - x;
    worst = std::max(worst, std::abs(error - last_error));
    last_error = error;
    t += k % 30 == 29 ? 8 * dt : dt;
  }
  return worst;
}
}  // namespace

TEST(LocalTracker, AGapOfDroppedScansIsPredictedAtConstantVelocity)
{
  TrackingParams tp;  // constant_velocity_horizon = 1 s
  EXPECT_LT(droppedScansJump(tp), 0.15);
  tp.constant_velocity_horizon = 0.05;  // scaled by max_interval_ratio = 4 at most
  EXPECT_GT(droppedScansJump(tp), 0.5) << "a gap predicted a quarter short should lose a post here";
}

TEST(LocalTracker, IrregularScanIntervalsArePredictedAtConstantVelocity)
{
  TrackingParams tp;
  const double with = corridorDrift(tp);
  tp.constant_velocity = false;
  const double without = corridorDrift(tp);
  EXPECT_LT(with, 0.1);
  EXPECT_GT(without, 1.0) << "the last step as the prediction should lose this corridor";
}

namespace
{
/** Across the room at 1 m/s, 10 scans a second; at scan `shut` a door swings shut 0.6 m in
 * front of the sensor and hides most of the room (the next keyframe then holds the door).
 * Returns, for that scan and the next two, whether it was searched, and the worst position
 * error among them [m]. */
std::pair<std::vector<bool>, double> doorSwingsShut(int shut, const TrackingParams& tp = TrackingParams())
{
  const auto room = test::roomWorld();
  std::mt19937 rng(12);
  LocalTracker tracker(tp, plicp::PlicpParams());
  std::vector<bool> searched;
  double worst = 0;
  for (int k = 0; k <= shut + 2; k++)
  {
    const CPose2D truth(-6 + 0.1 * k, -1, 0);
    auto world = room;
    const double door_x = -6 + 0.1 * shut + 0.6;
    if (k >= shut) world.segments.push_back({door_x, -3.5, door_x, 1.5});
    auto obs = test::simulateObservation(world, truth, 181, M_PI, 30, 0.01, rng);
    obs.timestamp = mrpt::Clock::fromDouble(1000 + 0.1 * k);
    const auto step = tracker.process(obs);
    if (k < shut) continue;
    if (k == shut) EXPECT_LT(step.match.inliers, 0.5 * step.valid_rays) << "the door should hide most of the room";
    searched.push_back(step.searched);
    worst = std::max(worst, (step.pose.translation() - ((-CPose2D(-6, -1, 0)) + truth).translation()).norm());
  }
  return {searched, worst};
}
}  // namespace

TEST(LocalTracker, AProvenPredictionIsKeptWhenTheSurroundingsChange)
{
  TrackingParams tp;  // trust_prediction_after = 10
  const auto [searched, worst] = doorSwingsShut(30, tp);
  EXPECT_EQ(searched, std::vector<bool>({false, false, false}));
  EXPECT_LT(worst, 0.05);
  // Not yet proven (5 scans before the door), or never trusted: the little overlap alone
  // calls for the search.
  EXPECT_TRUE(doorSwingsShut(5, tp).first.front());
  tp.trust_prediction_after = 0;
  EXPECT_TRUE(doorSwingsShut(30, tp).first.front());
}

TEST(LocalTracker, ADoorInFrontIsNotPutOnAWallElsewhere)
{
  // Searched (not yet a proven prediction), the door shut at scan 20 hides most of the room:
  // its first match stays on the prediction with few inliers, and the search's best pose puts
  // the door on a wall 2.4 m away with few inliers too. That pose replaces a match on its
  // prediction only with overlap_search_min_inlier_fraction of the rays: the first match
  // stays.
  TrackingParams tp;  // overlap_search_min_inlier_fraction = 0.2
  tp.trust_prediction_after = 0;
  EXPECT_LT(doorSwingsShut(20, tp).second, 0.1);
  tp.overlap_search_min_inlier_fraction = tp.searched_min_inlier_fraction;  // no higher bar
  EXPECT_GT(doorSwingsShut(20, tp).second, 1.0);
}

TEST(LocalTracker, DenseMatchesFarFromTheEstimateAreDropped)
{
  // An older node moved by 0.6 m: its dense match from the (now wrong) estimate converges to
  // the truth, 0.6 m from the guess, and the gate drops it.
  const auto world = test::clutteredWorld(5);
  const auto path = sCurve(60);
  for (double gate : {0.3, 10.0})
  {
    std::mt19937 rng(6);
    TrackingParams tp;
    tp.dense_gate_xy = gate;
    LocalTracker tracker(tp, plicp::PlicpParams());
    size_t moved = 0, edges_to_moved = 0, dense = 0;
    for (size_t k = 0; k < path.size(); k++)
    {
      if (k == 40)
      {
        moved = tracker.keyframes().size() - 2;
        tracker.setKeyframePose(moved, tracker.keyframes()[moved].pose + CPose2D(0.6, 0, 0));
      }
      const auto step = tracker.process(scanAt(world, path[k], CPose2D(), 0.05 * k, rng));
      for (const auto& e : step.edges)
      {
        if (e.kind != graph::EdgeKind::DenseNeighbour || k < 40) continue;
        dense++;
        edges_to_moved += e.from == moved;
      }
    }
    EXPECT_GT(dense, 5u) << "gate " << gate;
    if (gate < 1)
      EXPECT_EQ(edges_to_moved, 0u);
    else
      EXPECT_GT(edges_to_moved, 0u);
  }
}

namespace
{
struct WeakRun
{
  int ambiguous_scans = 0, fallback_scans = 0;
  int prior_decided_scans = 0;  ///< scans the prediction decided along a direction
  double worst_x_drift = 0;  ///< largest change of the along-x error past the posts [m]
  /** Largest change of the along-x error from one scan to the next, past the posts [m]: a
   * scan moved off the others (a steady drift of the prediction's speed counts too). */
  double worst_x_jump = 0;
  double worst_y_error = 0;
  double min_edge_x_variance = 1e300;  ///< of the consecutive edges past the posts, along x (vehicle frame)
};

/** At 1 m/s, 10 scans a second, along x from 0 to 5.9 m in `world` plus two posts at x = 1
 * and 2 m (181 beams over 180°, 8 m, 1 cm noise): the posts show the motion until the sensor
 * passes them at scan 20, and nothing tells it after that but the prediction, exact here at
 * constant velocity. Scan `blind` has no valid ray. */
WeakRun driveAlongX(test::World world, const TrackingParams& tp, int blind)
{
  world.circles.push_back({1.0, 0.7, 0.1});
  world.circles.push_back({2.0, -0.7, 0.1});
  std::mt19937 rng(21);
  LocalTracker tracker(tp, plicp::PlicpParams());
  WeakRun r;
  double x_error_20 = 0, x_error_previous = 0;
  for (int k = 0; k < 60; k++)
  {
    auto obs = test::simulateObservation(world, CPose2D(0.1 * k, 0, 0), 181, M_PI, 8, 0.01, rng);
    if (k == blind)
      for (size_t i = 0; i < obs.getScanSize(); i++) obs.setScanRangeValidity(i, false);
    obs.timestamp = mrpt::Clock::fromDouble(1000 + 0.1 * k);
    const auto step = tracker.process(obs);
    if (step.ambiguous > 0) r.ambiguous_scans++;
    if (step.prior_decided > 0) r.prior_decided_scans++;
    EXPECT_LE(step.prior_decided, step.ambiguous) << "scan " << k;
    if (step.source == TrackingSource::ConstantMotion) r.fallback_scans++;
    if (k == 20) x_error_20 = step.pose.x() - 0.1 * k;
    if (k >= 20) r.worst_x_drift = std::max(r.worst_x_drift, std::abs(step.pose.x() - 0.1 * k - x_error_20));
    if (k > 20) r.worst_x_jump = std::max(r.worst_x_jump, std::abs(step.pose.x() - 0.1 * k - x_error_previous));
    x_error_previous = step.pose.x() - 0.1 * k;
    r.worst_y_error = std::max(r.worst_y_error, std::abs(step.pose.y()));
    for (const auto& e : step.edges)
      if (e.kind == graph::EdgeKind::Consecutive && k >= 25)
        r.min_edge_x_variance = std::min(r.min_edge_x_variance, e.information.inverse()(0, 0));
  }
  return r;
}
}  // namespace

TEST(LocalTracker, AlongACorridorThePredictionDecidesAndTheEdgesSaySo)
{
  // Past the posts no ray faces the axis, which is unobservable, so the prediction decides
  // there; it keeps the speed the scans with the posts gave it, a steady drift, never a jump.
  TrackingParams tp;
  const WeakRun unobservable = driveAlongX(test::corridorWorld(), tp, 35);
  EXPECT_GE(unobservable.ambiguous_scans, 35);
  EXPECT_GE(unobservable.prior_decided_scans, 30) << "the scans past the posts";
  EXPECT_LT(unobservable.worst_x_jump, 0.05);
  EXPECT_LT(unobservable.worst_x_drift, 1.0);
  EXPECT_GE(unobservable.min_edge_x_variance, 0.02);
  // Weak directions only reported (and no choice between two matches left to the
  // prediction): the searches slide the scans along the axis by decimetres at a time, and the
  // noise's faked information makes confident edges along it.
  tp.unobservable_min_rays = 0;
  tp.prediction_decides_share = 0;
  const WeakRun reported = driveAlongX(test::corridorWorld(), tp, 35);
  EXPECT_GE(reported.ambiguous_scans, 35);
  EXPECT_EQ(reported.prior_decided_scans, 0);
  EXPECT_GT(reported.worst_x_jump, 0.3);
  EXPECT_LT(reported.min_edge_x_variance, 0.002);
  tp.ambiguity_factor = 0;
  const WeakRun off = driveAlongX(test::corridorWorld(), tp, 35);
  EXPECT_LT(off.min_edge_x_variance, 0.002);
}

TEST(LocalTracker, ASingleWallIsWeakAlongItself)
{
  test::World wall;
  wall.segments.push_back({-50, 1.5, 50, 1.5});
  // Once the posts are out of sight no ray faces the wall's line, which is then unobservable:
  // the prediction decides along it, and every scan is reported ambiguous. The prediction
  // keeps the speed the scans with the posts gave it (2.6 cm per scan short, here): a steady
  // drift, never a jump.
  TrackingParams tp;
  const WeakRun reported = driveAlongX(wall, tp, -1);
  EXPECT_GE(reported.ambiguous_scans, 35);
  EXPECT_GE(reported.prior_decided_scans, 35);
  EXPECT_EQ(reported.fallback_scans, 0);
  EXPECT_LT(reported.worst_x_jump, 0.05) << "no jump along the wall";
  EXPECT_LT(reported.worst_x_drift, 1.5);
  EXPECT_LT(reported.worst_y_error, 0.05);
  // Without the unobservable rule (nor the prediction's choice between two matches) the
  // searches slide the scans along the wall by metres.
  tp.unobservable_min_rays = 0;
  tp.prediction_decides_share = 0;
  const WeakRun slid = driveAlongX(wall, tp, -1);
  EXPECT_EQ(slid.prior_decided_scans, 0) << "weak directions only reported";
  EXPECT_GT(slid.worst_x_jump, 0.3);
  EXPECT_GT(slid.worst_x_drift, 3.0);
}

TEST(LocalTracker, ARoomIsNotAmbiguous)
{
  const WeakRun r = driveAlongX(test::roomWorld(), TrackingParams(), -1);
  EXPECT_EQ(r.ambiguous_scans, 0);
  EXPECT_EQ(r.prior_decided_scans, 0);
  EXPECT_LT(r.min_edge_x_variance, 0.01);
}

TEST(LocalTracker, AScanThatMatchesNothingBecomesNoNode)
{
  // Scan 40 sees other surroundings but for a 20 deg sector (a glitch of the sensor, say): the
  // search's best match explains under a tenth of its rays.
  const auto world = test::clutteredWorld(5), elsewhere = test::roomWorld();
  const auto path = sCurve(80);
  const size_t odd = 40;
  auto run = [&](const TrackingParams& tp) {
    std::mt19937 rng(6);
    TrackingParams always = tp;
    always.trust_prediction_after = 0;  // always search after a poor match, even on a proven prediction
    LocalTracker tracker(always, plicp::PlicpParams());
    std::vector<TrackingStep> steps;
    for (size_t k = 0; k < path.size(); k++)
    {
      auto obs = scanAt(world, path[k], CPose2D(), 0.05 * k, rng);
      if (k == odd)
      {
        const auto other = scanAt(elsewhere, CPose2D(), CPose2D(), 0.05 * k, rng);
        for (size_t i = 0; i < obs.getScanSize(); i++)
          if (i < 250 || i >= 290)
          {
            obs.setScanRange(i, other.getScanRange(i));
            obs.setScanRangeValidity(i, other.getScanRangeValidity(i));
          }
      }
      steps.push_back(tracker.process(obs));
    }
    return steps;
  };
  TrackingParams tp;
  tp.keyframe_translation = 0.05;  // every scan is past the keyframe threshold
  const auto steps = run(tp);
  EXPECT_EQ(steps[odd].source, TrackingSource::ConstantMotion);
  EXPECT_NE(steps[odd].match.message.find("searched_min_inlier_fraction"), std::string::npos) << steps[odd].match.message;
  EXPECT_FALSE(steps[odd].new_keyframe);
  for (size_t k = 1; k < path.size(); k++)
  {
    const CPose2D expected = (-path[0]) + path[k];
    EXPECT_LT((steps[k].pose.translation() - expected.translation()).norm(), 0.1 + 0.002 * k) << "scan " << k;
    if (k == odd) continue;
    EXPECT_TRUE(steps[k].new_keyframe) << "scan " << k;
    for (const auto& e : steps[k].edges) EXPECT_NE(e.kind, graph::EdgeKind::OdometryPrior) << "scan " << k;
  }
  // The scan after it is matched against the keyframe before it, across both intervals.
  EXPECT_EQ(steps[odd + 1].keyframe, steps[odd - 1].keyframe + 1);

  // Without the two rules, the search's best match becomes a node.
  tp.searched_min_inlier_fraction = 0;
  tp.unmatched_scans_skipped = 0;
  const auto before = run(tp);
  EXPECT_NE(before[odd].source, TrackingSource::ConstantMotion);
  EXPECT_TRUE(before[odd].new_keyframe);
}

TEST(LocalTracker, TheFirstMatchIsSearchedAlongACorridor)
{
  // A run starts in a corridor at 1 m per scan. The first prediction, no motion, is a guess:
  // PLICP keeps it (the walls agree at any shift), the search finds the end wall's shift.
  test::World world = test::corridorWorld();
  world.segments.push_back({6, -1, 6, 1});
  auto firstSteps = [&](const TrackingParams& tp, const correlative::CorrelativeParams& cp = {}) {
    std::mt19937 rng(8);
    LocalTracker tracker(tp, plicp::PlicpParams(), cp);
    std::vector<TrackingStep> steps;
    for (int k = 0; k < 4; k++)
    {
      auto obs = test::simulateObservation(world, CPose2D(1.0 * k, 0, 0), 181, M_PI, 8, 0.01, rng);
      obs.timestamp = mrpt::Clock::fromDouble(1000 + 0.1 * k);
      steps.push_back(tracker.process(obs));
    }
    return steps;
  };
  const auto steps = firstSteps(TrackingParams());
  EXPECT_TRUE(steps[1].searched);
  // Searched first: the match is PLICP's from the search's pose.
  EXPECT_EQ(steps[1].source, TrackingSource::Searched);
  for (int k = 1; k < 4; k++) EXPECT_NEAR(steps[k].pose.x(), 1.0 * k, 0.05) << "scan " << k;

  // A search that finds nothing (no pose can score above 1): PLICP from the guess after all.
  correlative::CorrelativeParams nothing;
  nothing.min_score = 1.5;
  const auto unfound = firstSteps(TrackingParams(), nothing);
  EXPECT_TRUE(unfound[1].searched);
  EXPECT_EQ(unfound[1].source, TrackingSource::Match);
  EXPECT_TRUE(unfound[1].match.ok()) << unfound[1].match.message;
  EXPECT_LT(unfound[1].pose.x(), 0.5) << "PLICP keeps the guess along the corridor";

  TrackingParams off;
  off.search_first_match = false;
  const auto unsearched = firstSteps(off);
  EXPECT_FALSE(unsearched[1].searched);
  EXPECT_LT(unsearched[1].pose.x(), 0.5) << "PLICP keeps the guess along the corridor";
}
