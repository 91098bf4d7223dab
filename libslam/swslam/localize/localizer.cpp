#include <swslam/localize/localizer.h>

#include <swslam/correlative/search.h>
#include <swslam/geometry/se2_error.h>
#include <swslam/geometry/se2_scaling.h>
#include <swslam/sensor/scan.h>

#include <mrpt/core/Clock.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swslam::localize
{
using mrpt::poses::CPose2D;

const char* toString(LocalizationState s)
{
  switch (s)
  {
    case LocalizationState::Tracked: return "tracked";
    case LocalizationState::Relocalized: return "relocalized";
    case LocalizationState::Predicted: return "predicted";
    case LocalizationState::Lost: return "lost";
  }
  return "?";
}

namespace
{
/** [m/s], [rad/s]: how fast a predicted pose's standard deviation grows since the last match. */
constexpr double kPredictedSigmaXyPerS = 0.1;
constexpr double kPredictedSigmaThetaPerS = 1.0 * M_PI / 180;
/** How far the match may move the whole-map search's pose and still confirm it: the search's
 * lattice step, twice, and a margin for PLICP's own settling. */
constexpr double kConfirmXyCells = 2.0;
constexpr double kConfirmXyMargin = 0.1;     ///< [m]
constexpr double kConfirmThetaSteps = 2.0;
constexpr double kConfirmThetaMargin = 1.0 * M_PI / 180;  ///< [rad]

/** Covariance of pose (+) mount^-1 (the vehicle) from that of pose (the sensor), first order. */
Eigen::Matrix3d vehicleCovariance(const CPose2D& sensor, const CPose2D& vehicle, const Eigen::Matrix3d& cov)
{
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  j(0, 2) = -(vehicle.y() - sensor.y());
  j(1, 2) = vehicle.x() - sensor.x();
  return j * cov * j.transpose();
}

Eigen::Matrix3d rotated(const Eigen::Matrix3d& cov, double phi)
{
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  r(0, 0) = r(1, 1) = std::cos(phi);
  r(1, 0) = std::sin(phi);
  r(0, 1) = -r(1, 0);
  return r * cov * r.transpose();
}
}  // namespace

Localizer::Localizer(const MapNodes& nodes, const Relocalizer& relocalizer, const LocalizerParams& params)
    : nodes_(nodes),
      relocalizer_(relocalizer),
      params_(params),
      forms_{params.plicp, params.correlative.resolution, params.correlative.max_range},
      matcher_(params.tracking, params.plicp, params.correlative)
{
}

void Localizer::setInitialPose(const CPose2D& pose)
{
  lost_ = false;
  pose_ = pose;
  last_motion_ = CPose2D();
  last_matched_time_.reset();
}

Localizer::NodeMatch Localizer::matchNode(const tracking::PreparedScan& scan, const CPose2D& mount,
                                          const CPose2D& vehicle_guess, bool measured)
{
  const CPose2D sensor_guess = vehicle_guess + mount;
  NodeMatch out;
  out.node = nodes_.nearest(sensor_guess, scan.rotationLength());
  if (!submap_ || submap_node_ != out.node)
  {
    const size_t node = out.node;
    // As many nodes as tracking's own submap holds keyframes.
    const size_t count = static_cast<size_t>(params_.tracking.submap_keyframes);
    const double range = params_.correlative.max_range;
    const MapNodes& nodes = nodes_;
    submap_ = std::make_unique<tracking::Submap>(nodes_.reference(node),
                                                 [&nodes, node, count, range] { return nodes.raysAround(node, count, range); });
    submap_node_ = node;
  }
  const CPose2D node_sensor = nodes_.sensorPose(out.node);
  tracking::Prediction p;
  p.guess = (-node_sensor) + sensor_guess;
  p.measured = measured;
  out.match = matcher_.match(*submap_, scan, p);
  const plicp::MatchResult& m = out.match.match;
  if (!m.ok()) return out;
  const CPose2D sensor = node_sensor + m.pose;
  out.vehicle = sensor + (-mount);
  out.covariance = vehicleCovariance(sensor, out.vehicle, rotated(m.covariance, node_sensor.phi()));
  out.inlier_fraction = scan.scan().empty() ? 0.0 : double(m.inliers) / double(scan.scan().size());
  out.good = !out.match.unmatched && out.inlier_fraction >= params_.localization.min_inlier_fraction;
  return out;
}

std::optional<Localizer::NodeMatch> Localizer::relocalize(const tracking::PreparedScan& scan, const CPose2D& mount,
                                                          const std::vector<Eigen::Vector2d>& points)
{
  const auto place = relocalizer_.find(points);
  if (!place || !place->distinct) return std::nullopt;
  const CPose2D sensor(place->pose.x(), place->pose.y(), place->pose.z());
  const CPose2D guess = sensor + (-mount);
  NodeMatch m = matchNode(scan, mount, guess, true);
  if (!m.good) return std::nullopt;
  // The match confirms the place only if it stays in the search's cell: a match that slid
  // away found something else than the search did.
  const double max_xy = kConfirmXyCells * relocalizer_.resolution() + kConfirmXyMargin;
  const double max_theta = kConfirmThetaSteps * params_.localization.theta_step + kConfirmThetaMargin;
  const CPose2D moved = (-guess) + m.vehicle;
  if (moved.norm() > max_xy || std::abs(moved.phi()) > max_theta) return std::nullopt;
  return m;
}

double Localizer::mapScore(const std::vector<Eigen::Vector2d>& points, const CPose2D& mount,
                           const CPose2D& vehicle) const
{
  const CPose2D sensor = vehicle + mount;
  return correlative::scoreAt(relocalizer_.grid(), points, {sensor.x(), sensor.y(), sensor.phi()});
}

CPose2D Localizer::predictedMotion(const std::optional<CPose2D>& odometry, double interval) const
{
  // As tracking predicts: the odometry, else the last motion at constant velocity.
  if (odometry) return *odometry;
  if (last_interval_ && *last_interval_ > 0 && interval > 0)
    return geometry::scaledMotion(last_motion_, std::clamp(interval / *last_interval_, 0.25, 4.0));
  return last_motion_;
}

LocalizedScan Localizer::track(const tracking::PreparedScan& scan, const CPose2D& mount, const CPose2D& motion,
                               double t)
{
  const CPose2D guess = pose_ + motion;
  const NodeMatch m = matchNode(scan, mount, guess, true);
  LocalizedScan out;
  out.node = m.node;
  out.inlier_fraction = m.inlier_fraction;
  // An initial pose counts as matched, and so does the last match when time stepped back
  // (the log's clock was set back): the time since it counts from here.
  if (!last_matched_time_ || t < *last_matched_time_) last_matched_time_ = t;
  if (m.good)
  {
    out.state = LocalizationState::Tracked;
    out.pose = m.vehicle;
    out.covariance = last_covariance_ = m.covariance;
    last_matched_time_ = t;
  }
  else
  {
    out.state = LocalizationState::Predicted;
    out.pose = guess;
    const double dt = std::max(0.0, t - *last_matched_time_);
    const double sxy = kPredictedSigmaXyPerS * dt, sth = kPredictedSigmaThetaPerS * dt;
    out.covariance = last_covariance_ + Eigen::Vector3d(sxy * sxy, sxy * sxy, sth * sth).asDiagonal().toDenseMatrix();
    lost_ = dt > params_.localization.lost_after;
  }
  if (!lost_)
  {
    last_motion_ = (-pose_) + out.pose;
    pose_ = out.pose;
  }
  return out;
}

LocalizedScan Localizer::searchMap(const tracking::PreparedScan& scan, const CPose2D& mount,
                                   const std::vector<Eigen::Vector2d>& points, const std::optional<CPose2D>& odometry,
                                   double t)
{
  LocalizedScan out;
  out.state = LocalizationState::Lost;
  out.covariance = Eigen::Matrix3d::Identity() * std::numeric_limits<double>::infinity();
  const bool due = !last_search_time_ || t < *last_search_time_ ||
                   t - *last_search_time_ >= params_.localization.relocalize_interval;
  if (!due) return out;
  last_search_time_ = t;
  out.searched_map = true;
  const std::optional<NodeMatch> m = relocalize(scan, mount, points);
  if (!m) return out;
  lost_ = false;
  out.state = LocalizationState::Relocalized;
  out.pose = pose_ = m->vehicle;
  out.covariance = last_covariance_ = m->covariance;
  out.node = m->node;
  out.inlier_fraction = m->inlier_fraction;
  last_motion_ = odometry ? *odometry : CPose2D();
  last_matched_time_ = t;
  return out;
}

LocalizedScan Localizer::localize(const sensor::ScanInput& input)
{
  const double t = mrpt::Clock::toDouble(input.observation->timestamp);
  sensor::Scan s = sensor::scanFromCheckedObservation(*input.observation, params_.tracking.min_range);
  const CPose2D mount = s.sensor_pose;
  nodes_.asMapSensor(s);
  const tracking::PreparedScan scan(std::move(s), forms_);
  const double interval = last_time_ ? t - *last_time_ : 0.0;
  // The points the map's grid scores (all of them, one per map cell): the whole-map search's
  // and the map score's.
  const std::vector<Eigen::Vector2d> map_points =
      correlative::thinPoints(scan.scan().points, relocalizer_.resolution(), std::numeric_limits<double>::infinity());

  LocalizedScan out;
  // The first scan after an initial pose is at that pose: the motion before it is not counted.
  const CPose2D motion = last_matched_time_ ? predictedMotion(input.odometry_increment, interval) : CPose2D();
  if (!lost_) out = track(scan, mount, motion, t);
  // Lost before this scan, or by it: the whole map is searched when due.
  if (lost_) out = searchMap(scan, mount, map_points, input.odometry_increment, t);
  out.valid_rays = scan.scan().size();
  if (out.state != LocalizationState::Lost) out.map_score = mapScore(map_points, mount, out.pose);
  if (interval > 0) last_interval_ = interval;
  last_time_ = t;
  return out;
}

}  // namespace swslam::localize
