#include <swslam/tracking/dense_edges.h>

#include <swslam/geometry/information.h>
#include <swslam/geometry/sensor_frame.h>
#include <swslam/tracking/weak_directions.h>

#include <algorithm>
#include <cmath>

namespace swslam::tracking
{
using mrpt::poses::CPose2D;

graph::Constraint consecutiveEdge(const Keyframe& previous, const Keyframe& node, const plicp::MatchResult& match,
                                  const TrackingParams& p)
{
  if (!match.ok()) return priorEdge(previous, node, p);
  graph::Constraint e{previous.id, node.id, geometry::vehicleMotion(previous.sensor_pose, match.pose),
                      Eigen::Matrix3d::Identity(), graph::EdgeKind::Consecutive};
  e.information = geometry::informationFromCovariance(
      geometry::vehicleMotionCovariance(previous.sensor_pose, match.pose, match.covariance));
  return e;
}

graph::Constraint priorEdge(const Keyframe& from, const Keyframe& to, const TrackingParams& p)
{
  graph::Constraint e;
  e.from = from.id;
  e.to = to.id;
  e.z = to.pose - from.pose;
  const double sxy = p.lost_prior_sigma_xy, sth = p.lost_prior_sigma_theta;
  e.information = Eigen::Vector3d(1 / (sxy * sxy), 1 / (sxy * sxy), 1 / (sth * sth)).asDiagonal();
  e.kind = graph::EdgeKind::OdometryPrior;
  return e;
}

std::optional<graph::Constraint> matchEdge(const Keyframe& from, const Keyframe& node, const PreparedScan& scan,
                                           graph::EdgeKind kind, const TrackingParams& p,
                                           const plicp::PlicpParams& plicp)
{
  // Guess from the current estimates; PLICP works in the sensor frame.
  const CPose2D guess = geometry::sensorMotion(from.sensor_pose, node.pose - from.pose);
  plicp::MatchResult m = plicp::matchScans(*from.scan, scan.scan(), guess, plicp);
  if (!m.ok()) return std::nullopt;
  takePriorWhereWeak(m, from, scan, guess, p.lost_prior_sigma_xy * p.lost_prior_sigma_xy, p, plicp);
  if ((m.pose.translation() - guess.translation()).norm() > p.dense_gate_xy ||
      std::abs(std::remainder(m.pose.phi() - guess.phi(), 2 * M_PI)) > p.dense_gate_theta)
    return std::nullopt;
  graph::Constraint e;
  e.from = from.id;
  e.to = node.id;
  e.z = geometry::vehicleMotion(from.sensor_pose, m.pose);
  e.information = geometry::informationFromCovariance(
      geometry::vehicleMotionCovariance(from.sensor_pose, m.pose, m.covariance));
  e.kind = kind;
  return e;
}

DenseEdges denseEdges(const std::vector<Keyframe>& keyframes, const PreparedScan& scan, const TrackingParams& p,
                      const plicp::PlicpParams& plicp)
{
  DenseEdges out;
  const Keyframe& node = keyframes.back();
  const size_t previous = node.id - 1;  // linked by the consecutive edge
  std::vector<std::pair<double, size_t>> near;
  const size_t gap = static_cast<size_t>(p.dense_max_index_gap);
  for (size_t id = node.id > gap ? node.id - gap : 0; id < previous; ++id)
  {
    const double d = (keyframes[id].pose.translation() - node.pose.translation()).norm();
    if (d <= p.dense_radius) near.emplace_back(d, id);
  }
  std::sort(near.begin(), near.end());
  near.resize(std::min(near.size(), static_cast<size_t>(p.max_dense_edges)));
  for (const auto& [d, id] : near)
  {
    out.tried++;
    if (auto e = matchEdge(keyframes[id], node, scan, graph::EdgeKind::DenseNeighbour, p, plicp))
      out.edges.push_back(*e);
  }
  return out;
}

}  // namespace swslam::tracking
