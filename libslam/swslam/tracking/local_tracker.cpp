#include <swslam/tracking/local_tracker.h>

#include <swslam/geometry/information.h>
#include <swslam/geometry/sensor_frame.h>
#include <swslam/tracking/dense_edges.h>
#include <swslam/tracking/motion_prediction.h>
#include <swslam/tracking/weak_directions.h>

#include <mrpt/system/datetime.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swslam::tracking
{
using mrpt::poses::CPose2D;

const char* toString(TrackingSource s)
{
  switch (s)
  {
    case TrackingSource::First: return "first";
    case TrackingSource::Match: return "match";
    case TrackingSource::Searched: return "searched";
    case TrackingSource::Odometry: return "odometry";
    case TrackingSource::ConstantMotion: return "constant_motion";
  }
  return "unknown";
}

LocalTracker::LocalTracker(const TrackingParams& tracking, const plicp::PlicpParams& plicp,
                           const correlative::CorrelativeParams& correlative)
    : tracking_(tracking),
      plicp_(plicp),
      correlative_(correlative),
      forms_{plicp, correlative.resolution, correlative.max_range},
      matcher_(tracking, plicp, correlative)
{
}

TrackingStep LocalTracker::process(const mrpt::obs::CObservation2DRangeScan& obs,
                                   const std::optional<CPose2D>& odometry_increment)
{
  const PreparedScan scan(sensor::scanFromCheckedObservation(obs, tracking_.min_range), forms_);
  const double interval =
      keyframes_.empty() ? 0.0 : mrpt::system::timeDifference(last_time_, scan.scan().timestamp);
  last_time_ = scan.scan().timestamp;
  TrackingStep step;
  step.valid_rays = scan.scan().size();
  if (keyframes_.empty())
  {
    addKeyframe(scan, CPose2D());
    step.new_keyframe = true;
    return step;
  }
  const Keyframe& last = keyframes_.back();
  const Predicted predicted = predict(odometry_increment, interval);
  const auto t0 = std::chrono::steady_clock::now();
  ScanMatch m = matcher_.match(*submap_, scan, predicted.sensor);
  step.match_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  step.searched = m.searched;
  step.source = m.replaced ? TrackingSource::Searched : TrackingSource::Match;
  const plicp::MatchResult raw = m.match;  // before the prediction decides its weak directions
  decideAmbiguity(m, scan, predicted, step);
  step.match = m.match;
  CPose2D rel = predicted.relative;
  if (step.match.ok())
    rel = geometry::vehicleMotion(last.sensor_pose, step.match.pose);
  else
    step.source = odometry_increment ? TrackingSource::Odometry : TrackingSource::ConstantMotion;
  advance(rel, raw, predicted);
  step.keyframe = last.id;
  step.relative = rel;
  step.pose = last.pose + rel;
  // A new keyframe lies exactly on itself (its consecutive edge carries the match); a scan
  // between keyframes keeps its match's information for its place in the trajectory.
  if (makesNode(rel, step.match.ok()))
    addNode(scan, step);
  else if (step.match.ok())
    step.relative_information = geometry::informationFromCovariance(
        geometry::vehicleMotionCovariance(last.sensor_pose, step.match.pose, step.match.covariance));
  return step;
}

void LocalTracker::resume(const std::vector<CPose2D>& poses,
                          const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& observations)
{
  if (!keyframes_.empty()) throw std::logic_error("tracking: a session is resumed before the first scan");
  if (poses.empty() || observations.size() != poses.size())
    throw std::invalid_argument("tracking: a resumed session needs one observation per node pose (" +
                                std::to_string(observations.size()) + " for " + std::to_string(poses.size()) + ")");
  const size_t first_kept = poses.size() > kept() ? poses.size() - kept() : 0;
  for (size_t id = 0; id < poses.size(); id++)
  {
    if (id < first_kept)
    {
      Keyframe kf;
      kf.id = id;
      kf.pose = poses[id];
      keyframes_.push_back(std::move(kf));
      continue;
    }
    if (!observations[id])
      throw std::invalid_argument("tracking: resumed node " + std::to_string(id) + " has no observation");
    addKeyframe(PreparedScan(sensor::scanFromCheckedObservation(*observations[id], tracking_.min_range), forms_),
                poses[id]);
  }
  last_time_ = keyframes_.back().timestamp;
}

void LocalTracker::addNode(const PreparedScan& scan, TrackingStep& step)
{
  // The consecutive edge from the match (or, without one, a weak prior that says so), then
  // dense edges to the recent nodes within the radius, nearest first.
  const size_t previous = keyframes_.back().id;
  const Keyframe& node = addKeyframe(scan, step.pose);
  step.edges.push_back(consecutiveEdge(keyframes_[previous], node, step.match, tracking_));
  DenseEdges dense = denseEdges(keyframes_, scan, tracking_, plicp_);
  step.edges.insert(step.edges.end(), dense.edges.begin(), dense.edges.end());
  step.dense_matches = dense.tried;
  step.new_keyframe = true;
  step.keyframe = node.id;
  step.relative = CPose2D();
  relative_ = CPose2D();
}

LocalTracker::Predicted LocalTracker::predict(const std::optional<CPose2D>& odometry_increment, double interval)
{
  // The paper predicts the previous motion; here at constant velocity over this scan's
  // interval. Odometry, when present, is the better prediction.
  Predicted p;
  p.motion = last_motion_;
  if (odometry_increment)
    p.motion = *odometry_increment;
  else if (tracking_.constant_velocity)
    p.motion =
        geometry::scaledMotion(last_motion_, intervalRatio(interval, last_interval_, tracking_.max_interval_ratio,
                                                           tracking_.constant_velocity_horizon));
  last_interval_ = interval;
  p.relative = relative_ + p.motion;
  p.sensor.guess = geometry::sensorMotion(keyframes_.back().sensor_pose, p.relative);
  p.sensor.measured = odometry_increment.has_value() || motion_matched_;
  p.sensor.cost_per_m2 = steady_.costPerM2(tracking_);
  const double lost_var = tracking_.lost_prior_sigma_xy * tracking_.lost_prior_sigma_xy;
  p.sensor.variance = steady_.predictionVariance(plicp_.range_sigma * plicp_.range_sigma, lost_var);
  return p;
}

void LocalTracker::decideAmbiguity(ScanMatch& m, const PreparedScan& scan, const Predicted& predicted,
                                   TrackingStep& step) const
{
  // Along a direction no surface faces, the prediction decides, with the variance its recent
  // errors show (and the keyframe edge knows it).
  const WeakDirections weak = takePriorWhereWeak(m.match, keyframes_.back(), scan, predicted.sensor.guess,
                                                 predicted.sensor.variance, tracking_, plicp_);
  step.ambiguous = weak.weak + (m.second_peak ? 1 : 0) + (m.prediction_chose ? 1 : 0);
  step.prior_decided = weak.prior_decided + (m.prediction_chose ? 1 : 0);
  // A match that is one of two poses the scan cannot tell apart: its variance along their
  // separation is the separation's square (after the weak directions: the prediction never
  // averages two peaks).
  if (m.second_peak) m.match.covariance += *m.second_peak * m.second_peak->transpose();
}

void LocalTracker::advance(const CPose2D& rel, const plicp::MatchResult& raw, const Predicted& predicted)
{
  last_motion_ = rel - relative_;
  motion_matched_ = motion_matched_ || raw.ok();
  // The error of the prediction this scan used, measured by the match before the prediction
  // replaced its weak directions (which would confirm it there by construction).
  const Keyframe& last = keyframes_.back();
  steady_.add(raw.ok() ? geometry::vehicleMotion(last.sensor_pose, raw.pose) - relative_ : last_motion_,
              predicted.motion);
  relative_ = rel;
}

bool LocalTracker::makesNode(const CPose2D& rel, bool matched)
{
  unmatched_in_a_row_ = matched ? 0 : unmatched_in_a_row_ + 1;
  if (!(rel.norm() > tracking_.keyframe_translation || std::abs(rel.phi()) > tracking_.keyframe_rotation))
    return false;
  // A node needs a match, unless the scans have gone unmatched for longer than one odd scan
  // explains (open water, a blind sensor): then the prediction makes nodes with weak edges.
  return matched || unmatched_in_a_row_ > static_cast<size_t>(tracking_.unmatched_scans_skipped);
}

Keyframe& LocalTracker::addKeyframe(const PreparedScan& scan, const CPose2D& pose)
{
  Keyframe kf;
  kf.id = keyframes_.size();
  kf.pose = pose;
  kf.scan = scan.reference();
  kf.facing = scan.facing();
  kf.sensor_pose = scan.scan().sensor_pose;
  kf.timestamp = scan.scan().timestamp;
  keyframes_.push_back(std::move(kf));
  // Memory grows with the keyframes' poses, not with their scans.
  if (keyframes_.size() > kept())
  {
    Keyframe& old = keyframes_[keyframes_.size() - 1 - kept()];
    old.scan.reset();
    old.facing.reset();
  }
  submap_ = std::make_unique<Submap>(keyframes_.back().scan, [this] { return submapRays(); });
  return keyframes_.back();
}

size_t LocalTracker::kept() const
{
  return static_cast<size_t>(std::max(tracking_.dense_max_index_gap + 1, tracking_.submap_keyframes));
}

std::vector<correlative::Ray> LocalTracker::submapRays() const
{
  // The last keyframes' rays up to max_range, in the last keyframe's sensor frame:
  // s_last^-1 (+) x_last^-1 (+) x_k (+) s_k.
  const Keyframe& last = keyframes_.back();
  const CPose2D to_last_sensor = -(last.pose + last.sensor_pose);
  std::vector<correlative::Ray> out;
  const size_t n = static_cast<size_t>(tracking_.submap_keyframes);
  for (size_t k = keyframes_.size() > n ? keyframes_.size() - n : 0; k < keyframes_.size(); k++)
  {
    const Keyframe& kf = keyframes_[k];
    const CPose2D t = to_last_sensor + (kf.pose + kf.sensor_pose);
    const Eigen::Vector2d origin(t.x(), t.y());
    for (const auto& p : kf.scan->scan.points)
    {
      if (p.norm() > correlative_.max_range) continue;
      double x, y;
      t.composePoint(p.x(), p.y(), x, y);
      out.push_back({origin, {x, y}});
    }
  }
  return out;
}

void LocalTracker::setKeyframePose(size_t id, const CPose2D& pose)
{
  keyframes_.at(id).pose = pose;
}

}  // namespace swslam::tracking
