#include <swslam/tracking/local_tracker.h>
#include <swslam/geometry/information.h>

#include <swslam/correlative/peaks.h>
#include <swslam/correlative/searched_match.h>
#include <swslam/tracking/ambiguity.h>
#include <swslam/geometry/sensor_frame.h>
#include <swslam/tracking/motion_prediction.h>

#include <mrpt/system/datetime.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
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
    : tracking_(tracking), plicp_(plicp), correlative_(correlative)
{
}

std::vector<correlative::Ray> LocalTracker::submapRays() const
{
  // The last keyframes' rays up to max_range, in the last keyframe's sensor frame:
  // s_last^-1 (+) x_last^-1 (+) x_k (+) s_k.
  const Keyframe& last = keyframes_.back();
  const CPose2D to_last_sensor = -(last.pose + last.sensor_pose);
  std::vector<correlative::Ray> out;
  const size_t n = static_cast<size_t>(correlative_.submap_keyframes);
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

plicp::MatchResult LocalTracker::matchLast(const sensor::Scan& scan, const CPose2D& guess, bool measured_prediction,
                                           TrackingStep& step)
{
  const Keyframe& last = keyframes_.back();
  // A prediction that no matched motion or odometry backs (a run's first match: "no motion")
  // is a guess, not a measurement. Along a corridor PLICP keeps it at any speed, so the
  // search decides, and PLICP runs from the search's pose alone (from the guess only if the
  // search finds no match).
  const bool search_first =
      correlative_.enabled && correlative::searchFirst(measured_prediction, tracking_.search_first_match);
  plicp::MatchResult m = search_first ? correlative::notRun(guess) : matchReference(scan, guess);
  if (!correlative_.enabled) return m;
  const correlative::SearchTrigger why = correlative::searchTrigger(m, guess, correlative_);
  // Once trust_prediction_after scans in a row confirmed their predictions, a match that
  // stays on its prediction is kept even with little overlap, until a match fails or moves
  // its guess: the surroundings are new or changed (a door swung shut), which the submap
  // cannot explain and the search would explain elsewhere.
  const bool proven = correlative_.trust_prediction_after > 0 &&
                      confirmed_in_a_row_ >= static_cast<size_t>(correlative_.trust_prediction_after);
  if (why == correlative::SearchTrigger::None) confirmed_in_a_row_++;
  // The count goes on through such scans: a door passes by over several of them.
  if (!correlative::searchNeeded(why, measured_prediction, tracking_.search_first_match, proven)) return m;
  confirmed_in_a_row_ = 0;
  if (!search_pyramid_ || search_pyramid_keyframe_ != last.id)
  {
    search_pyramid_ = std::make_shared<const correlative::ScorePyramid>(
        correlative::searchPyramid(submapRays(), correlative_));
    search_pyramid_keyframe_ = last.id;
  }
  // Where the two matches differ along a direction the scans cannot decide, the prediction
  // chooses between them, if its recent errors are small enough to tell them apart.
  const double lost_var = tracking_.lost_prior_sigma_xy * tracking_.lost_prior_sigma_xy;
  correlative::SearchedMatch s = correlative::searchAndMatch(
      *last.scan, *search_pyramid_, scan, guess, m, correlative_, plicp_, steady_.costPerM2(correlative_),
      steady_.predictionVariance(plicp_.range_sigma * plicp_.range_sigma, lost_var));
  step.searched = true;
  step.prediction_chose = s.prediction_decided;
  if (search_first && !s.replaced) s.match = m = matchReference(scan, guess);
  // A first match that stayed on its prediction lost only overlap: an object close in front
  // of the sensor hides the surroundings, and the search may put that object on a wall of the
  // map far away. The search's match replaces it only if it explains more of the scan than a
  // match that only stands in for a failed or moved one must; else the first match stays.
  const correlative::AfterSearch kept = correlative::afterSearch(
      why, s, tracking_.overlap_search_min_inlier_fraction, tracking_.searched_min_inlier_fraction);
  if (kept == correlative::AfterSearch::KeepFirst) return m;
  if (kept == correlative::AfterSearch::Unmatched)
  {
    // Neither the prediction nor the search explains the scan: an odd scan (someone in front
    // of the sensor) or surroundings the keyframes never saw. It is unmatched rather than a
    // confident wrong pose: the prediction carries it.
    plicp::MatchResult unmatched = s.match;
    unmatched.status = plicp::MatchStatus::TooFewCorrespondences;
    unmatched.message = "the search's best match has " + std::to_string(s.match.inliers) + " inliers of " +
                        std::to_string(s.match.cur_valid_rays) + " valid rays (searched_min_inlier_fraction)";
    return unmatched;
  }
  if (s.replaced) step.source = TrackingSource::Searched;
  if (s.match.ok())
    if (const auto d = secondPeakOffset(scan, guess, s.match))
    {
      step.two_peaks = true;
      step.peak_offset = *d;
    }
  return s.match;
}

plicp::MatchResult LocalTracker::matchReference(const sensor::Scan& scan, const CPose2D& guess) const
{
  return plicp::matchScans(*keyframes_.back().scan, scan, guess, plicp_);
}

graph::Constraint LocalTracker::consecutiveEdge(const Keyframe& previous, const Keyframe& node,
                                                const plicp::MatchResult& match) const
{
  if (!match.ok()) return priorEdge(previous, node);
  const plicp::MatchResult& m = match;
  graph::Constraint e{previous.id, node.id, geometry::vehicleMotion(previous.sensor_pose, m.pose),
                      Eigen::Matrix3d::Identity(), graph::EdgeKind::Consecutive};
  e.information = geometry::informationFromCovariance(
      geometry::vehicleMotionCovariance(previous.sensor_pose, m.pose, m.covariance));
  return e;
}

std::optional<Eigen::Vector3d> LocalTracker::secondPeakOffset(const sensor::Scan& scan, const CPose2D& guess,
                                                              const plicp::MatchResult& m) const
{
  correlative::SearchWindow w = correlative::searchWindow(correlative_, guess);
  w.cost_per_m2 = steady_.costPerM2(correlative_);
  const Eigen::Vector3d chosen(m.pose.x(), m.pose.y(), m.pose.phi());
  const auto peak = correlative::secondPeak(
      *search_pyramid_, correlative::thinPoints(scan.points, correlative_.resolution, correlative_.max_range), w,
      chosen, correlative::peakRadius(correlative_.sigma, correlative_.resolution), correlative_.min_score,
      correlative_.min_score_gain);
  if (!peak || !peak->similar) return std::nullopt;
  Eigen::Vector3d d = peak->peak.pose - chosen;
  d.z() = std::remainder(d.z(), 2 * M_PI);
  return d;
}

Keyframe& LocalTracker::addKeyframe(const sensor::Scan& scan, const CPose2D& pose)
{
  Keyframe kf;
  kf.id = keyframes_.size();
  kf.pose = pose;
  kf.scan = std::make_shared<const plicp::ReferenceScan>(scan, plicp_);
  kf.facing = std::make_shared<const FacingNormals>(facingNormals(scan.points, plicp_.min_segment_length));
  kf.sensor_pose = scan.sensor_pose;
  kf.timestamp = scan.timestamp;
  keyframes_.push_back(std::move(kf));
  return keyframes_.back();
}

bool LocalTracker::pastKeyframeThreshold(const CPose2D& rel) const
{
  return rel.norm() > tracking_.keyframe_translation ||
         std::abs(rel.phi()) > tracking_.keyframe_rotation;
}

LocalTracker::WeakDirections LocalTracker::takePriorWhereWeak(plicp::MatchResult& m, const plicp::ReferenceScan& ref,
                                                              const FacingNormals& ref_facing, const sensor::Scan& cur,
                                                              const FacingNormals* cur_facing, const CPose2D& prior,
                                                              double prior_var_xy, double length) const
{
  if (!m.ok() || tracking_.ambiguity_factor <= 0) return {};
  const double noise = residualNoiseVariance(m.sum_sq_residuals, m.correspondences, plicp_.range_sigma * plicp_.range_sigma);
  const double threshold = weakRatioThreshold(noise, plicp_.min_segment_length, tracking_.ambiguity_factor);
  const Ambiguity a = findWeakDirections(m.covariance, length, threshold);
  // Along a direction no surface faces, the match moved by noise alone (a single wall lets the
  // scans slide along it by metres): the prediction decides there, whatever the setting. The
  // match's two weaker directions are candidates whatever their information says: a wall's
  // line can look informed by the noise of one scan (about one in ten on a simulated wall).
  Ambiguity taken = a;
  taken.weak = 0;
  const Ambiguity candidates = findWeakDirections(m.covariance, length, 1.0);
  // Only a match whose weakest direction has less than kFacingCheckRatio times the weak
  // threshold's information is tested: the scan's normals and the counts for every match
  // cost 0.04-0.06 ms per scan on the valley (doc/tracking.md).
  if (tracking_.unobservable_min_rays > 0 && candidates.ratio < kFacingCheckRatio * threshold)
  {
    FacingNormals own;
    if (!cur_facing) own = facingNormals(cur.points, plicp_.min_segment_length);
    taken = unobservableDirections(candidates, {ref.scan.points, ref_facing, 0.0},
                                   {cur.points, cur_facing ? *cur_facing : own, m.pose.phi()}, length,
                                   tracking_.unobservable_min_rays);
  }
  if (taken.weak == 0) return {a.weak, 0};
  const double sth = tracking_.lost_prior_sigma_theta;
  Eigen::Vector3d x(m.pose.x(), m.pose.y(), m.pose.phi());
  takePriorAlongWeak(x, m.covariance, Eigen::Vector3d(prior.x(), prior.y(), prior.phi()),
                     Eigen::Vector3d(prior_var_xy, prior_var_xy, sth * sth).asDiagonal(), taken, length);
  m.pose = CPose2D(x.x(), x.y(), x.z());
  return {std::max(a.weak, taken.weak), taken.weak};
}

std::optional<graph::Constraint> LocalTracker::matchEdge(const Keyframe& from, const Keyframe& to,
                                                   const sensor::Scan& scan, graph::EdgeKind kind) const
{
  // Guess from the current estimates; PLICP works in the sensor frame.
  const CPose2D guess = geometry::sensorMotion(from.sensor_pose, to.pose - from.pose);
  plicp::MatchResult m = plicp::matchScans(*from.scan, scan, guess, plicp_);
  if (!m.ok()) return std::nullopt;
  // Along a direction the pair does not constrain, the chain decides, with the variance of a
  // node made without a match: never a confident pull along a corridor.
  takePriorWhereWeak(m, *from.scan, *from.facing, scan, to.facing.get(), guess,
                     tracking_.lost_prior_sigma_xy * tracking_.lost_prior_sigma_xy, sensor::rotationLength(scan.points));
  // The chain between recent nodes is accurate to centimetres: a match far from it found
  // another local minimum (low overlap, repeated structure), not a correction.
  if ((m.pose.translation() - guess.translation()).norm() > tracking_.dense_gate_xy ||
      std::abs(std::remainder(m.pose.phi() - guess.phi(), 2 * M_PI)) > tracking_.dense_gate_theta)
    return std::nullopt;
  graph::Constraint e;
  e.from = from.id;
  e.to = to.id;
  e.z = geometry::vehicleMotion(from.sensor_pose, m.pose);
  e.information = geometry::informationFromCovariance(
      geometry::vehicleMotionCovariance(from.sensor_pose, m.pose, m.covariance));
  e.kind = kind;
  return e;
}

graph::Constraint LocalTracker::priorEdge(const Keyframe& from, const Keyframe& to) const
{
  graph::Constraint e;
  e.from = from.id;
  e.to = to.id;
  e.z = to.pose - from.pose;
  const double sxy = tracking_.lost_prior_sigma_xy, sth = tracking_.lost_prior_sigma_theta;
  e.information = Eigen::Vector3d(1 / (sxy * sxy), 1 / (sxy * sxy), 1 / (sth * sth)).asDiagonal();
  e.kind = graph::EdgeKind::OdometryPrior;
  return e;
}

TrackingStep LocalTracker::process(const mrpt::obs::CObservation2DRangeScan& obs,
                                   const std::optional<CPose2D>& odometry_increment)
{
  const sensor::Scan scan = sensor::scanFromCheckedObservation(obs, tracking_.min_range);
  // Seconds since the previous scan (0 for the first).
  const double interval =
      keyframes_.empty() ? 0.0 : mrpt::system::timeDifference(last_time_, scan.timestamp);
  last_time_ = scan.timestamp;
  TrackingStep step;
  step.valid_rays = scan.size();
  if (keyframes_.empty())
  {
    addKeyframe(scan, CPose2D());
    step.new_keyframe = true;
    return step;
  }
  const Keyframe& last = keyframes_.back();
  // Initial guess: the previous relative pose moved by the expected motion (the paper uses
  // the previous motion, here at constant velocity over this scan's interval; odometry, when
  // present, is the better prediction).
  CPose2D motion = last_motion_;
  if (odometry_increment)
    motion = *odometry_increment;
  else if (tracking_.constant_velocity)
    motion = geometry::scaledMotion(last_motion_, intervalRatio(interval, last_interval_, tracking_.max_interval_ratio));
  last_interval_ = interval;
  const CPose2D predicted = relative_ + motion;
  const auto t0 = std::chrono::steady_clock::now();
  step.source = TrackingSource::Match;
  step.match = matchLast(scan, geometry::sensorMotion(last.sensor_pose, predicted),
                         odometry_increment.has_value() || motion_matched_, step);
  step.match_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CPose2D rel = predicted;
  // Where the match is ambiguous, the prediction decides, with the variance its recent errors
  // show (and the keyframe edge knows it). The errors are measured by the match before the
  // prediction replaced its weak directions, which would confirm it there by construction.
  const plicp::MatchResult raw = step.match;
  const double lost_var = tracking_.lost_prior_sigma_xy * tracking_.lost_prior_sigma_xy;
  const WeakDirections weak =
      takePriorWhereWeak(step.match, *last.scan, *last.facing, scan, nullptr,
                         geometry::sensorMotion(last.sensor_pose, predicted),
                         steady_.predictionVariance(plicp_.range_sigma * plicp_.range_sigma, lost_var),
                         sensor::rotationLength(scan.points));
  step.ambiguous = weak.weak + (step.two_peaks ? 1 : 0) + (step.prediction_chose ? 1 : 0);
  step.prior_decided = weak.prior_decided + (step.prediction_chose ? 1 : 0);
  // A match that is one of two poses the scan cannot tell apart: its variance along their
  // separation is the separation's square (after the weak directions: the prediction never
  // averages two peaks).
  if (step.two_peaks) step.match.covariance += step.peak_offset * step.peak_offset.transpose();
  if (step.match.ok())
    rel = geometry::vehicleMotion(last.sensor_pose, step.match.pose);
  else
    step.source = odometry_increment ? TrackingSource::Odometry : TrackingSource::ConstantMotion;
  last_motion_ = rel - relative_;
  motion_matched_ = motion_matched_ || step.match.ok();
  // The error of the prediction this scan used.
  steady_.add(raw.ok() ? geometry::vehicleMotion(last.sensor_pose, raw.pose) - relative_ : last_motion_, motion);
  relative_ = rel;
  step.keyframe = last.id;
  step.relative = rel;
  step.pose = last.pose + rel;
  const bool unmatched = !step.match.ok();
  unmatched_in_a_row_ = unmatched ? unmatched_in_a_row_ + 1 : 0;
  if (!pastKeyframeThreshold(rel)) return step;
  // A node needs a match, unless the scans have gone unmatched for longer than one odd scan
  // explains (open water, a blind sensor): then the prediction makes nodes with weak edges.
  if (unmatched && unmatched_in_a_row_ <= static_cast<size_t>(tracking_.unmatched_scans_skipped)) return step;

  // A new node: the consecutive edge from the match (or, without one, a weak prior that says
  // so), then dense edges to every other node within the radius, nearest first.
  const size_t prev_id = keyframes_.back().id;
  Keyframe& node = addKeyframe(scan, step.pose);
  const Keyframe& previous = keyframes_[prev_id];
  step.edges.push_back(consecutiveEdge(previous, node, step.match));
  // Only recent nodes: older ones within reach are loop candidates, verified by the graph.
  std::vector<std::pair<double, size_t>> near;
  const size_t gap = static_cast<size_t>(tracking_.dense_max_index_gap);
  for (size_t id = node.id > gap ? node.id - gap : 0; id < prev_id; ++id)
  {
    const Keyframe& kf = keyframes_[id];
    const double d = (kf.pose.translation() - node.pose.translation()).norm();
    if (d <= tracking_.dense_radius) near.emplace_back(d, kf.id);
  }
  std::sort(near.begin(), near.end());
  near.resize(std::min(near.size(), static_cast<size_t>(tracking_.max_dense_edges)));
  for (const auto& [d, id] : near)
  {
    step.dense_matches++;
    if (auto e = matchEdge(keyframes_[id], node, scan, graph::EdgeKind::DenseNeighbour)) step.edges.push_back(*e);
  }
  step.new_keyframe = true;
  step.keyframe = node.id;
  step.relative = CPose2D();
  relative_ = CPose2D();
  return step;
}

void LocalTracker::setKeyframePose(size_t id, const CPose2D& pose)
{
  keyframes_.at(id).pose = pose;
}

}  // namespace swslam::tracking
