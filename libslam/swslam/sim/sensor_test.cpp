// The simulated LiDAR honours its parameters: noise level, dropouts, range limits,
// beam geometry and mounting pose.
#include <swslam/sensor/scan.h>
#include <swslam/sim/sensor.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam::sim;

namespace
{
/** A closed ring of short segments of radius `r` around (cx, cy). */
World ringWorld(double r, double cx = 0, double cy = 0)
{
  World w;
  w.bounds = {-30, -30, 30, 30};
  const int n = 720;
  for (int i = 0; i < n; i++)
  {
    const double a0 = 2 * M_PI * i / n, a1 = 2 * M_PI * (i + 1) / n;
    w.add(Shape::segment(ShapeKind::Bank, {cx + r * std::cos(a0), cy + r * std::sin(a0)},
                         {cx + r * std::cos(a1), cy + r * std::sin(a1)}));
  }
  return w;
}

SensorParams sensor()
{
  SensorParams p;
  p.fov = M_PI;
  p.resolution = M_PI / 360;  // 361 rays
  p.max_range = 20;
  p.min_range = 0.1;
  p.range_noise_std = 0.05;
  p.dropout_prob = 0.1;
  return p;
}
}  // namespace

TEST(SimSensor, NoiseAndDropoutsFollowTheParameters)
{
  const World w = ringWorld(10);
  const ShapeGrid grid(w, 2.0);
  const SensorParams p = sensor();
  LidarSimulator lidar(p, grid, 9);
  ASSERT_EQ(lidar.rays(), 361u);
  double sum = 0, sum2 = 0;
  size_t valid = 0, total = 0;
  for (uint64_t k = 0; k < 100; k++)
  {
    const mrpt::poses::CPose2D pose(0.1 * k / 100.0, 0, 0.01 * k);
    const auto obs = lidar.scan(pose, mrpt::Clock::fromDouble(k), k);
    for (size_t i = 0; i < obs->getScanSize(); i++, total++)
    {
      if (!obs->getScanRangeValidity(i)) continue;
      const double e = obs->getScanRange(i) - lidar.trueRange(pose, i, k);
      sum += e;
      sum2 += e * e;
      valid++;
    }
  }
  const double mean = sum / valid, sd = std::sqrt(sum2 / valid - mean * mean);
  EXPECT_NEAR(static_cast<double>(valid) / total, 1 - p.dropout_prob, 0.01);
  EXPECT_NEAR(mean, 0, 0.003);
  EXPECT_NEAR(sd, p.range_noise_std, 0.003);
}

TEST(SimSensor, BeyondMaxOrBelowMinRangeIsInvalidAtMaxRange)
{
  SensorParams p = sensor();
  p.dropout_prob = 0;
  p.range_noise_std = 0;
  for (double radius : {25.0, 0.05})  // beyond max range; inside min range
  {
    const World w = ringWorld(radius);
    const ShapeGrid grid(w, 2.0);
    LidarSimulator lidar(p, grid, 1);
    const auto obs = lidar.scan(mrpt::poses::CPose2D(), mrpt::Clock::fromDouble(0), 0);
    for (size_t i = 0; i < obs->getScanSize(); i++)
    {
      EXPECT_FALSE(obs->getScanRangeValidity(i));
      EXPECT_FLOAT_EQ(obs->getScanRange(i), p.max_range);
    }
  }
}

TEST(SimSensor, ReturnsProjectOntoTheWallFromTheMountedSensor)
{
  // Off-centre ring, sensor mounted ahead of the vehicle and turned: every return,
  // projected through the vehicle pose and the mounting pose, lands on the ring.
  const World w = ringWorld(8, 1.0, -0.5);
  const ShapeGrid grid(w, 1.0);
  SensorParams p = sensor();
  p.dropout_prob = 0;
  p.range_noise_std = 0;
  p.pose_x = 0.5;
  p.pose_y = 0.2;
  p.pose_yaw = 0.3;
  LidarSimulator lidar(p, grid, 2);
  const mrpt::poses::CPose2D vehicle(0.7, 0.4, 2.0);
  const auto obs = lidar.scan(vehicle, mrpt::Clock::fromDouble(0), 0);
  const swslam::sensor::Scan s = swslam::sensor::scanFromObservation(*obs);
  ASSERT_EQ(s.size(), 361u);
  EXPECT_NEAR(s.sensor_pose.phi(), 0.3, 1e-9);
  for (const auto& q : s.points)
  {
    const auto g = vehicle + s.sensor_pose + mrpt::poses::CPose2D(q.x(), q.y(), 0);
    // Chords of the 720-gon sit at most r (1 - cos(pi/720)) inside the circle.
    EXPECT_NEAR(std::hypot(g.x() - 1.0, g.y() + 0.5), 8.0, 1e-4);
  }
}
