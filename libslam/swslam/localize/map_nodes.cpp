#include <swslam/localize/map_nodes.h>

#include <swslam/geometry/se2_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace swslam::localize
{
using mrpt::poses::CPose2D;

MapNodes::MapNodes(const std::vector<CPose2D>& poses, std::vector<sensor::Scan> scans,
                   const plicp::PlicpParams& plicp)
    : poses_(poses), store_(plicp)
{
  if (poses.size() != scans.size())
    throw std::invalid_argument("map nodes: " + std::to_string(poses.size()) + " poses but " +
                                std::to_string(scans.size()) + " scans");
  if (poses.empty()) throw std::invalid_argument("map nodes: the map has no node");
  label_ = scans.front().sensor_label;
  beam_count_ = scans.front().beam_count;
  aperture_ = scans.front().aperture;
  for (size_t id = 1; id < scans.size(); ++id)
  {
    const sensor::Scan& s = scans[id];
    if (s.sensor_label != label_ || s.beam_count != beam_count_ || std::abs(s.aperture - aperture_) > 1e-6 ||
        (s.sensor_pose - scans.front().sensor_pose).norm() > 1e-9 ||
        std::abs(geometry::wrapAngle(s.sensor_pose.phi() - scans.front().sensor_pose.phi())) > 1e-9)
      throw std::invalid_argument("map nodes: node " + std::to_string(id) + "'s scan comes from another sensor than node 0's ('" +
                                  s.sensor_label + "', " + std::to_string(s.beam_count) + " beams, vs '" + label_ +
                                  "', " + std::to_string(beam_count_) + "): a map of one sensor is localized on");
  }
  mounts_.reserve(scans.size());
  for (size_t id = 0; id < scans.size(); ++id)
  {
    mounts_.push_back(scans[id].sensor_pose);
    store_.add(id, std::make_shared<const plicp::ReferenceScan>(std::move(scans[id]), plicp));
  }
}

void MapNodes::asMapSensor(sensor::Scan& scan) const
{
  scan.sensor_label = label_;
  scan.beam_count = beam_count_;
  scan.aperture = aperture_;
  scan.sensor_pose = mounts_.front();
}

size_t MapNodes::nearest(const CPose2D& sensor_pose, double rotation_length) const
{
  size_t best = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (size_t id = 0; id < poses_.size(); ++id)
  {
    const CPose2D s = sensorPose(id);
    const double cost = std::hypot(s.x() - sensor_pose.x(), s.y() - sensor_pose.y()) +
                        rotation_length * std::abs(geometry::wrapAngle(s.phi() - sensor_pose.phi()));
    if (cost < best_cost)
    {
      best_cost = cost;
      best = id;
    }
  }
  return best;
}

std::vector<correlative::Ray> MapNodes::raysAround(size_t id, size_t count, double max_range) const
{
  const CPose2D centre = sensorPose(id);
  std::vector<std::pair<double, size_t>> by_distance;
  for (size_t k = 0; k < poses_.size(); ++k)
  {
    const CPose2D s = sensorPose(k);
    const double d = std::hypot(s.x() - centre.x(), s.y() - centre.y());
    if (k == id)
      by_distance.emplace_back(-1.0, k);
    else if (d <= 2 * max_range)
      by_distance.emplace_back(d, k);
  }
  const size_t n = std::min(count, by_distance.size());
  std::partial_sort(by_distance.begin(), by_distance.begin() + n, by_distance.end());
  const CPose2D to_centre = -centre;
  std::vector<correlative::Ray> out;
  for (size_t i = 0; i < n; ++i)
  {
    const CPose2D t = to_centre + sensorPose(by_distance[i].second);
    const Eigen::Vector2d origin(t.x(), t.y());
    for (const auto& p : store_.get(by_distance[i].second)->scan.points)
    {
      if (p.norm() > max_range) continue;
      double x, y;
      t.composePoint(p.x(), p.y(), x, y);
      out.push_back({origin, {x, y}});
    }
  }
  return out;
}

}  // namespace swslam::localize
