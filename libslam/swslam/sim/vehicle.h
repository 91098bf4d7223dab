#pragma once
// The simulated vehicle: a smooth (C1) Catmull-Rom path through waypoints driven at
// constant speed, with its heading along the path, and a noisy odometry channel.

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <random>
#include <vector>

namespace swslam::sim
{
class VehiclePath
{
 public:
  /** Builds the path through `waypoints` (closed: back to the first one, with a
   * continuous heading). Throws std::invalid_argument on repeated waypoints. */
  VehiclePath(const std::vector<Eigen::Vector2d>& waypoints, bool closed, double speed);

  double length() const { return s_.back(); }
  double duration() const { return length() / speed_; }
  double speed() const { return speed_; }

  /** Pose at time t in [0, duration()] (clamped), heading along the path. */
  mrpt::poses::CPose2D poseAt(double t) const;

  /** Largest |curvature| of the path [1/m]; the turn rate is speed * curvature. */
  double maxCurvature() const { return max_curvature_; }
  /** Where the curvature is largest. */
  Eigen::Vector2d maxCurvaturePoint() const { return max_curvature_point_; }

  /** Dense samples of the path (about every 0.2 m). */
  const std::vector<Eigen::Vector2d>& samples() const { return pts_; }

 private:
  /** Uniform Catmull-Rom segment: cubic c0 + c1 u + c2 u^2 + c3 u^3, u in [0, 1]. */
  struct Segment
  {
    Eigen::Vector2d c0, c1, c2, c3;
    Eigen::Vector2d at(double u) const { return c0 + u * (c1 + u * (c2 + u * c3)); }
    Eigen::Vector2d d1(double u) const { return c1 + u * (2 * c2 + 3 * u * c3); }
    Eigen::Vector2d d2(double u) const { return 2 * c2 + 6 * u * c3; }
  };
  double speed_;
  std::vector<Segment> segments_;
  std::vector<Eigen::Vector2d> pts_;  ///< positions of the dense samples
  std::vector<size_t> seg_;           ///< segment of each sample
  std::vector<double> u_;             ///< spline parameter of each sample in its segment
  std::vector<double> s_;             ///< arc length at each sample
  double max_curvature_ = 0;
  Eigen::Vector2d max_curvature_point_ = Eigen::Vector2d::Zero();
};

/** Odometry as a wheel/propeller encoder would report it: the true increments
 * between consecutive poses with a relative speed error, a constant yaw-rate bias
 * and a random yaw error per step, integrated from the first true pose. */
class OdometrySimulator
{
 public:
  OdometrySimulator(double speed_noise_std, double yaw_drift, double yaw_noise_std,
                    uint64_t seed);

  /** Odometry pose at `truth`, `dt` seconds after the previous call (the first call
   * returns `truth` itself). */
  mrpt::poses::CPose2D next(const mrpt::poses::CPose2D& truth, double dt);

 private:
  double speed_noise_std_, yaw_drift_, yaw_noise_std_;
  std::mt19937_64 rng_;
  bool started_ = false;
  mrpt::poses::CPose2D last_truth_, odom_;
};

}  // namespace swslam::sim
