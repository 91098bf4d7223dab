#include <swslam/loop/closer.h>

#include <swslam/geometry/information.h>

#include <swslam/correlative/peaks.h>
#include <swslam/correlative/search.h>
#include <swslam/correlative/search_setup.h>
#include <swslam/geometry/sensor_frame.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace swslam::loop
{
using mrpt::poses::CPose2D;

const char* toString(LoopCheck::Verdict v)
{
  switch (v)
  {
    case LoopCheck::Verdict::Accepted: return "accepted";
    case LoopCheck::Verdict::MatchFailed: return "match_failed";
    case LoopCheck::Verdict::PoorOverlap: return "poor_overlap";
    case LoopCheck::Verdict::GateRejected: return "gate_rejected";
  }
  return "unknown";
}

std::vector<size_t> loopCandidates(const graph::PoseGraph& graph, size_t newest, const LoopClosureParams& p,
                                   const std::function<double(size_t)>& path_length)
{
  const CPose2D& here = graph.pose(newest);  // throws for a missing node
  const auto gap = static_cast<size_t>(p.min_index_gap);
  if (!p.enabled || p.max_candidates <= 0 || newest < gap) return {};
  const auto& linked_edges = graph.edgesOf(newest);
  auto linked = [&](size_t id) {
    return std::any_of(linked_edges.begin(), linked_edges.end(), [&](size_t e) {
      const auto& edge = graph.edge(e);
      return edge.from == id || edge.to == id;
    });
  };
  // The node map is ordered by id: walk the ids old enough, stop past the last one.
  std::vector<std::pair<double, size_t>> near;
  const auto& nodes = graph.network().nodes;
  std::vector<std::pair<double, size_t>> far;  // beyond max_distance, within the drift's reach
  const double here_path = path_length ? path_length(newest) : 0;
  for (auto it = nodes.begin(); it != nodes.end() && it->first < newest; ++it)
  {
    if (it->first + gap > newest) break;
    const double d = (it->second.translation() - here.translation()).norm();
    if (graph.isMerged(it->first) || linked(it->first)) continue;
    if (d <= p.max_distance)
      near.emplace_back(d, it->first);
    else if (path_length && d <= p.max_search_radius)
    {
      const double reach = 3 * p.drift_xy_per_m * std::abs(here_path - path_length(it->first));
      if (d <= reach) far.emplace_back(d / reach, it->first);
    }
  }
  if (near.empty() && !far.empty())
  {
    std::sort(far.begin(), far.end());
    return {far.front().second};  // the one the drift explains best
  }
  std::sort(near.begin(), near.end());
  near.resize(std::min(near.size(), static_cast<size_t>(p.max_candidates)));
  std::vector<size_t> ids;
  for (const auto& n : near) ids.push_back(n.second);
  return ids;
}

Eigen::Matrix3d driftCovariance(double path_gap, const LoopClosureParams& p)
{
  const double gap = std::abs(path_gap);
  const double sxy = std::max(p.drift_xy_per_m * gap, p.min_drift_sigma_xy);
  const double sth = std::max(p.drift_theta_per_m * gap, p.min_drift_sigma_theta);
  return Eigen::Vector3d(sxy * sxy, sxy * sxy, sth * sth).asDiagonal();
}

double loopMahalanobis2(const CPose2D& predicted, const CPose2D& measured,
                        const Eigen::Matrix3d& measured_cov, const Eigen::Matrix3d& drift_cov)
{
  // MRPT: a - b is b^-1 (+) a. Its translation R(pred)' (t_meas - t_pred) and its angle
  // phi_meas - phi_pred are linear in the measurement, so J is exact.
  const CPose2D err = measured - predicted;
  const Eigen::Vector3d e(err.x(), err.y(), mrpt::math::wrapToPi(err.phi()));
  const double c = std::cos(predicted.phi()), s = std::sin(predicted.phi());
  Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
  J.topLeftCorner<2, 2>() << c, s, -s, c;
  const Eigen::Matrix3d S = J * measured_cov * J.transpose() + drift_cov;
  const Eigen::LLT<Eigen::Matrix3d> llt(0.5 * (S + S.transpose()));
  if (!S.allFinite() || !e.allFinite() || llt.info() != Eigen::Success)
    return std::numeric_limits<double>::infinity();
  return e.dot(llt.solve(e));
}

double matchInlierFraction(const plicp::MatchResult& m)
{
  return m.cur_valid_rays == 0 ? 0.0 : static_cast<double>(m.correspondences) / m.cur_valid_rays;
}

namespace
{
/** PLICP from the best pose of a correlative search on the old scan alone, around `guess`
 * (sensor frame) within 3 drift standard deviations, capped by window_xy (a `far` candidate's:
 * max_search_radius); `first` when the search finds nothing or
 * is ambiguous (a pose farther than ambiguity_radius from the best scores within
 * ambiguity_margin of it: a self-similar place, where a loop is better missed). */
plicp::MatchResult searchedLoopMatch(const plicp::ReferenceScan& old_scan, const sensor::Scan& cur, const CPose2D& guess,
                              const plicp::MatchResult& first, const Eigen::Matrix3d& drift, bool far,
                              correlative::CorrelativeParams s, const LoopClosureParams& p, const plicp::PlicpParams& plicp)
{
  // A far candidate (beyond max_distance) is searched as far as the drift reaches.
  s.window_xy = std::min(far ? p.max_search_radius : s.window_xy, 3 * std::sqrt(drift(0, 0)));
  s.window_theta = std::min(s.window_theta, 3 * std::sqrt(drift(2, 2)));
  const correlative::ScorePyramid pyramid = correlative::searchPyramid(correlative::scanRays(old_scan.scan, s.max_range), s);
  const auto points = correlative::thinPoints(cur.points, s.resolution, s.max_range);
  correlative::SearchWindow w = correlative::searchWindow(s, guess);
  const auto best = correlative::searchBranchAndBound(pyramid, points, w, s.min_score);
  if (!best) return first;
  if (p.ambiguity_radius > 0)
  {
    const auto runner_up = correlative::secondPeak(pyramid, points, w, best->pose, p.ambiguity_radius, s.min_score,
                                                   p.ambiguity_margin, best->objective);
    if (runner_up && runner_up->similar) return first;
  }
  return plicp::matchScans(old_scan, cur, CPose2D(best->pose.x(), best->pose.y(), best->pose.z()), plicp);
}
}  // namespace

LoopCheck verifyLoop(const graph::PoseGraph& graph, const LoopNode& old, const LoopNode& newest,
                     const LoopClosureParams& p, const plicp::PlicpParams& plicp,
                     const std::optional<correlative::CorrelativeParams>& search)
{
  if (!old.scan || !newest.scan)
    throw std::invalid_argument("verifyLoop: node " + std::to_string(old.scan ? newest.id : old.id) +
                                " has no scan");
  if (old.id == newest.id)
    throw std::invalid_argument("verifyLoop: node " + std::to_string(old.id) + " paired with itself");
  LoopCheck c;
  c.from = old.id;
  c.to = newest.id;
  const CPose2D& from_pose = graph.pose(old.id);  // both throw for a missing node
  const CPose2D& to_pose = graph.pose(newest.id);
  c.distance = (to_pose.translation() - from_pose.translation()).norm();
  c.path_gap = std::abs(newest.path_length - old.path_length);
  c.predicted = to_pose - from_pose;

  // PLICP works in the sensor frame (the mounting is the same: matchScans checks it).
  const CPose2D& mount = old.scan->scan.sensor_pose;
  const CPose2D guess = geometry::sensorMotion(mount, c.predicted);
  c.match = plicp::matchScans(*old.scan, newest.scan->scan, guess, plicp);
  const Eigen::Matrix3d drift = driftCovariance(c.path_gap, p);
  if (search && search->enabled && old.scan->scan.sensor_pose == newest.scan->scan.sensor_pose &&
      (c.match.status != plicp::MatchStatus::Converged || matchInlierFraction(c.match) < p.min_inlier_fraction))
  {
    const plicp::MatchResult m = searchedLoopMatch(*old.scan, newest.scan->scan, guess, c.match, drift,
                                                   c.distance > p.max_distance, *search, p, plicp);
    c.searched = m.status != c.match.status || !(m.pose == c.match.pose);
    c.match = m;
  }
  if (c.match.status != plicp::MatchStatus::Converged) return c;  // verdict MatchFailed
  c.inlier_fraction = matchInlierFraction(c.match);
  const CPose2D measured = geometry::vehicleMotion(mount, c.match.pose);
  const Eigen::Matrix3d cov = geometry::vehicleMotionCovariance(mount, c.match.pose, c.match.covariance);
  c.mahalanobis2 = loopMahalanobis2(c.predicted, measured, cov, drift);
  if (c.inlier_fraction < p.min_inlier_fraction)
    c.verdict = LoopCheck::Verdict::PoorOverlap;
  else if (!(c.mahalanobis2 <= p.chi2_gate))
    c.verdict = LoopCheck::Verdict::GateRejected;
  else
  {
    c.verdict = LoopCheck::Verdict::Accepted;
    c.edge = graph::Constraint{old.id, newest.id, measured, geometry::informationFromCovariance(cov), graph::EdgeKind::Loop};
  }
  return c;
}

std::vector<LoopCheck> checkLoops(const graph::PoseGraph& graph, const LoopNode& newest,
                                  const std::function<LoopNode(size_t)>& node,
                                  const std::function<double(size_t)>& path_length,
                                  const LoopClosureParams& p, const plicp::PlicpParams& plicp,
                                  const std::optional<correlative::CorrelativeParams>& search)
{
  std::vector<LoopCheck> checks;
  for (const size_t id : loopCandidates(graph, newest.id, p, path_length))
    checks.push_back(verifyLoop(graph, node(id), newest, p, plicp, search));
  return checks;
}

}  // namespace swslam::loop
