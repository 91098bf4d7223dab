#include "swslam/sim_vehicle.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
constexpr double kSampleSpacing = 0.2;  // [m] between dense samples

// Uniform Catmull-Rom segment from p1 to p2: position, first and second derivative.
struct CatmullRom
{
  Eigen::Vector2d c0, c1, c2, c3;
  CatmullRom(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2,
             const Eigen::Vector2d& p3)
      : c0(p1),
        c1(0.5 * (p2 - p0)),
        c2(0.5 * (2 * p0 - 5 * p1 + 4 * p2 - p3)),
        c3(0.5 * (-p0 + 3 * p1 - 3 * p2 + p3))
  {
  }
  Eigen::Vector2d at(double u) const { return c0 + u * (c1 + u * (c2 + u * c3)); }
  Eigen::Vector2d d1(double u) const { return c1 + u * (2 * c2 + 3 * u * c3); }
  Eigen::Vector2d d2(double u) const { return 2 * c2 + 6 * u * c3; }
};
}  // namespace

VehiclePath::VehiclePath(const std::vector<Eigen::Vector2d>& waypoints, bool closed, double speed)
    : speed_(speed)
{
  const size_t n = waypoints.size();
  if (n < 2) throw std::invalid_argument("path: need at least 2 waypoints");
  for (size_t i = 0; i + 1 < n + (closed ? 1 : 0); i++)
    if ((waypoints[(i + 1) % n] - waypoints[i]).norm() < 1e-3)
      throw std::invalid_argument("path: waypoints " + std::to_string(i) + " and " +
                                  std::to_string((i + 1) % n) + " coincide");
  if (closed && n < 3) throw std::invalid_argument("path: a closed path needs 3 waypoints");

  // Control point k, extended past the ends (closed: wrap; open: mirror the end).
  const auto P = [&](long k) -> Eigen::Vector2d {
    const long m = static_cast<long>(n);
    if (closed) return waypoints[((k % m) + m) % m];
    if (k < 0) return 2 * waypoints[0] - waypoints[1];
    if (k >= m) return 2 * waypoints[m - 1] - waypoints[m - 2];
    return waypoints[k];
  };
  const long segments = static_cast<long>(closed ? n : n - 1);
  pts_.push_back(waypoints[0]);
  s_.push_back(0);
  heading_.push_back(0);
  for (long k = 0; k < segments; k++)
  {
    const CatmullRom seg(P(k - 1), P(k), P(k + 1), P(k + 2));
    const int steps = std::max(8, static_cast<int>(std::ceil((P(k + 1) - P(k)).norm() /
                                                             kSampleSpacing)));
    for (int j = (k == 0 ? 0 : 1); j <= steps; j++)
    {
      const double u = static_cast<double>(j) / steps;
      const Eigen::Vector2d p = seg.at(u), d = seg.d1(u), dd = seg.d2(u);
      const double speed2 = d.squaredNorm();
      if (speed2 < 1e-12) throw std::invalid_argument("path: cusp between waypoints");
      const double kappa = std::abs(d.x() * dd.y() - d.y() * dd.x()) / std::pow(speed2, 1.5);
      if (kappa > max_curvature_)
      {
        max_curvature_ = kappa;
        max_curvature_point_ = p;
      }
      double h = std::atan2(d.y(), d.x());
      if (k == 0 && j == 0)
      {
        heading_[0] = h;
        continue;
      }
      // Unwrap so that interpolation between samples never jumps by 2 pi.
      h = heading_.back() + mrpt::math::wrapToPi(h - heading_.back());
      s_.push_back(s_.back() + (p - pts_.back()).norm());
      pts_.push_back(p);
      heading_.push_back(h);
    }
  }
}

mrpt::poses::CPose2D VehiclePath::poseAt(double t) const
{
  const double s = std::clamp(t * speed_, 0.0, length());
  const size_t i = std::min<size_t>(
      static_cast<size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()), s_.size() - 1);
  const size_t i0 = i - 1;
  const double ds = s_[i] - s_[i0];
  const double f = ds > 0 ? (s - s_[i0]) / ds : 0.0;
  const Eigen::Vector2d p = pts_[i0] + f * (pts_[i] - pts_[i0]);
  const double h = heading_[i0] + f * (heading_[i] - heading_[i0]);
  return mrpt::poses::CPose2D(p.x(), p.y(), mrpt::math::wrapToPi(h));
}

OdometrySimulator::OdometrySimulator(double speed_noise_std, double yaw_drift,
                                     double yaw_noise_std, uint64_t seed)
    : speed_noise_std_(speed_noise_std),
      yaw_drift_(yaw_drift),
      yaw_noise_std_(yaw_noise_std),
      rng_(seed)
{
}

mrpt::poses::CPose2D OdometrySimulator::next(const mrpt::poses::CPose2D& truth, double dt)
{
  if (!started_)
  {
    started_ = true;
    last_truth_ = odom_ = truth;
    return odom_;
  }
  std::normal_distribution<double> N(0.0, 1.0);
  // True increment in the vehicle frame, then scaled translation and biased rotation.
  const mrpt::poses::CPose2D inc = truth - last_truth_;
  const double scale = 1.0 + speed_noise_std_ * N(rng_);
  const double dyaw = inc.phi() + yaw_drift_ * dt + yaw_noise_std_ * N(rng_);
  odom_ = odom_ + mrpt::poses::CPose2D(inc.x() * scale, inc.y() * scale, dyaw);
  last_truth_ = truth;
  return odom_;
}

}  // namespace swslam::sim
