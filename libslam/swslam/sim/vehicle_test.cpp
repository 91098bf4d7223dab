// The simulated vehicle: a continuous path at the set speed with a bounded turn rate,
// and odometry that drifts exactly as configured.
#include <swslam/sim/vehicle.h>

#include <mrpt/math/wrap2pi.h>

#include <gtest/gtest.h>

#include <cmath>

using swslam::sim::OdometrySimulator;
using swslam::sim::VehiclePath;

namespace
{
std::vector<Eigen::Vector2d> loopWaypoints()
{
  return {{0, -20}, {18, -12}, {22, 6}, {8, 20}, {-12, 18}, {-22, 0}, {-15, -16}};
}

/** Poses sampled at `rate` respect the speed and the path's own turn-rate bound. */
void expectContinuous(const VehiclePath& path, double rate)
{
  const double dt = 1.0 / rate, v = path.speed();
  const double max_turn = path.maxCurvature() * v;
  auto prev = path.poseAt(0);
  for (double t = dt; t <= path.duration(); t += dt)
  {
    const auto p = path.poseAt(t);
    const double step = std::hypot(p.x() - prev.x(), p.y() - prev.y());
    ASSERT_LE(step, 1.005 * v * dt) << "t = " << t;  // arc length from a 0.2 m table
    ASSERT_GE(step, 0.98 * v * dt) << "t = " << t;  // chords of a smooth curve
    ASSERT_LE(std::abs(mrpt::math::wrapToPi(p.phi() - prev.phi())), 1.05 * max_turn * dt + 1e-6)
        << "t = " << t;
    // The heading follows the direction of travel (the chord's, halfway).
    const double travel = std::atan2(p.y() - prev.y(), p.x() - prev.x());
    const double mid = prev.phi() + 0.5 * mrpt::math::wrapToPi(p.phi() - prev.phi());
    ASSERT_LT(std::abs(mrpt::math::wrapToPi(travel - mid)), 1e-3) << "t = " << t;
    prev = p;
  }
}
}  // namespace

TEST(SimVehicle, ClosedPathIsContinuousAndReturnsToStart)
{
  const VehiclePath path(loopWaypoints(), true, 1.5);
  expectContinuous(path, 40);
  const auto a = path.poseAt(0), b = path.poseAt(path.duration());
  EXPECT_NEAR(a.x(), b.x(), 1e-9);
  EXPECT_NEAR(a.y(), b.y(), 1e-9);
  EXPECT_NEAR(mrpt::math::wrapToPi(a.phi() - b.phi()), 0, 1e-3);
  // The loop is longer than the waypoint polygon's perimeter minus corner cuts, and
  // not much longer than it.
  double polygon = 0;
  const auto w = loopWaypoints();
  for (size_t i = 0; i < w.size(); i++) polygon += (w[(i + 1) % w.size()] - w[i]).norm();
  EXPECT_GT(path.length(), 0.95 * polygon);
  EXPECT_LT(path.length(), 1.15 * polygon);
}

TEST(SimVehicle, OpenPathPassesThroughWaypoints)
{
  const std::vector<Eigen::Vector2d> w{{0, 0}, {10, 2}, {20, 0}, {30, 3}};
  const VehiclePath path(w, false, 2.0);
  expectContinuous(path, 25);
  const auto end = path.poseAt(path.duration() + 5);  // clamped to the end
  EXPECT_NEAR(end.x(), 30, 1e-9);
  EXPECT_NEAR(end.y(), 3, 1e-9);
  for (const auto& p : w)
  {
    double best = 1e9;
    for (const auto& s : path.samples()) best = std::min(best, (s - p).norm());
    EXPECT_LT(best, 1e-9);
  }
  EXPECT_THROW(VehiclePath({{0, 0}, {0, 0}}, false, 1.0), std::invalid_argument);
}

TEST(SimVehicle, CurvatureOfCircleLikeLoop)
{
  // Waypoints on a circle of radius 20: curvature close to 1/20.
  std::vector<Eigen::Vector2d> w;
  for (int i = 0; i < 24; i++)
    w.emplace_back(20 * std::cos(2 * M_PI * i / 24), 20 * std::sin(2 * M_PI * i / 24));
  const VehiclePath path(w, true, 1.0);
  EXPECT_NEAR(path.maxCurvature(), 1.0 / 20, 0.003);  // a spline, not a circle
  EXPECT_NEAR(path.length(), 2 * M_PI * 20, 0.1);
}

TEST(SimVehicle, OdometryWithoutNoiseIsTruthAndDriftAccumulates)
{
  const VehiclePath path(loopWaypoints(), true, 1.5);
  OdometrySimulator exact(0, 0, 0, 1);
  const double drift = 0.01, dt = 0.05;  // rad/s
  OdometrySimulator drifting(0, drift, 0, 1);
  double t = 0;
  for (; t <= path.duration(); t += dt)
  {
    const auto truth = path.poseAt(t);
    const auto o = exact.next(truth, dt);
    ASSERT_NEAR(o.x(), truth.x(), 1e-6);
    ASSERT_NEAR(o.y(), truth.y(), 1e-6);
    ASSERT_NEAR(mrpt::math::wrapToPi(o.phi() - truth.phi()), 0, 1e-9);
    const auto d = drifting.next(truth, dt);
    ASSERT_NEAR(mrpt::math::wrapToPi(d.phi() - truth.phi()),
                mrpt::math::wrapToPi(drift * std::round(t / dt) * dt), 1e-6);
  }
}
