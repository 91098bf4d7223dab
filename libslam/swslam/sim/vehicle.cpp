#include <swslam/sim/vehicle.h>


#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
constexpr double kSampleSpacing = 0.2;  // [m] between dense samples

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
  for (long k = 0; k < segments; k++)
  {
    const Eigen::Vector2d p0 = P(k - 1), p1 = P(k), p2 = P(k + 1), p3 = P(k + 2);
    segments_.push_back({p1, 0.5 * (p2 - p0), 0.5 * (2 * p0 - 5 * p1 + 4 * p2 - p3),
                         0.5 * (-p0 + 3 * p1 - 3 * p2 + p3)});
    const Segment& seg = segments_.back();
    const int steps =
        std::max(8, static_cast<int>(std::ceil((p2 - p1).norm() / kSampleSpacing)));
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
      s_.push_back(pts_.empty() ? 0.0 : s_.back() + (p - pts_.back()).norm());
      pts_.push_back(p);
      seg_.push_back(static_cast<size_t>(k));
      u_.push_back(u);
    }
  }
}

mrpt::poses::CPose2D VehiclePath::poseAt(double t) const
{
  // Arc length -> spline parameter by interpolating the dense table, then the exact
  // spline point with its tangent as heading.
  const double s = std::clamp(t * speed_, 0.0, length());
  const size_t i = std::clamp<size_t>(
      static_cast<size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()), 1,
      s_.size() - 1);
  const size_t k = seg_[i];
  const double u0 = seg_[i - 1] == k ? u_[i - 1] : 0.0;  // a segment's start is u = 0
  const double ds = s_[i] - s_[i - 1];
  const double u = u0 + (ds > 0 ? (s - s_[i - 1]) / ds : 0.0) * (u_[i] - u0);
  const Eigen::Vector2d p = segments_[k].at(u), d = segments_[k].d1(u);
  return mrpt::poses::CPose2D(p.x(), p.y(), std::atan2(d.y(), d.x()));
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
