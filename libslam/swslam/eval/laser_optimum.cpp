#include <swslam/eval/laser_optimum.h>
#include <swslam/geometry/information.h>

#include <swslam/eval/ate.h>
#include <swslam/eval/consistency.h>
#include <swslam/geometry/pose_threshold.h>
#include <swslam/graph/edge_kind.h>
#include <swslam/loop/closer.h>
#include <swslam/tracking/local_tracker.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace swslam::eval
{
using mrpt::poses::CPose2D;

namespace
{
geometry::Pose2 asVector(const CPose2D& p) { return geometry::Pose2(p.x(), p.y(), p.phi()); }
}  // namespace

LaserOptimumOptions laserOptimumOptions(const tracking::TrackingParams& tracking, const loop::LoopClosureParams& loops)
{
  LaserOptimumOptions o;
  o.radius = tracking.dense_radius;
  o.dense_max_index_gap = static_cast<size_t>(tracking.dense_max_index_gap);
  o.gate_xy = tracking.dense_gate_xy;
  o.gate_theta = tracking.dense_gate_theta;
  o.min_inlier_fraction = loops.min_inlier_fraction;
  o.failed_sigma_xy = tracking.lost_prior_sigma_xy;
  o.failed_sigma_theta = tracking.lost_prior_sigma_theta;
  return o;
}

LaserOptimumResult laserOptimum(const std::vector<sensor::Scan>& scans, const std::vector<CPose2D>& sensor_poses,
                                const plicp::PlicpParams& plicp, const graph::GraphOptimizerParams& graph,
                                const LaserOptimumOptions& options)
{
  if (scans.size() != sensor_poses.size() || scans.size() < 2)
    throw std::invalid_argument("laser optimum: one pose per scan, at least two scans (got " +
                                std::to_string(scans.size()) + " scans, " +
                                std::to_string(sensor_poses.size()) + " poses)");
  LaserOptimumResult result;
  graph::GraphProblem problem;
  for (const auto& p : sensor_poses) problem.poses.push_back(asVector(p));
  problem.fixed.assign(scans.size(), 0);
  problem.fixed[0] = 1;
  const auto pairs = nearbyPairs(sensor_poses, options.radius, 1);
  std::vector<char> consecutive_linked(scans.size(), 0);
  const auto match = [&](size_t i, size_t j, const plicp::ReferenceScan& ref) {
    result.pairs++;
    const CPose2D guess = sensor_poses[j] - sensor_poses[i];
    const plicp::MatchResult m = plicp::matchScans(ref, scans[j], guess, plicp);
    if (!m.ok() || loop::matchInlierFraction(m) < options.min_inlier_fraction ||
        geometry::movedBeyond(guess, m.pose, geometry::MoveThreshold{options.gate_xy, options.gate_theta}))
      return;
    const graph::EdgeKind kind = j == i + 1                              ? graph::EdgeKind::Consecutive
                          : j - i <= options.dense_max_index_gap ? graph::EdgeKind::DenseNeighbour
                                                                  : graph::EdgeKind::Loop;
    problem.edges.push_back({static_cast<int>(i), static_cast<int>(j), asVector(m.pose),
                             geometry::informationFromCovariance(m.covariance), graph.isRobust(kind)});
    if (kind == graph::EdgeKind::Consecutive) consecutive_linked[j] = 1;
  };
  // Pairs come sorted by i: one reference index per older scan.
  for (size_t k = 0, i = 0; i + 1 < scans.size(); ++i)
  {
    const plicp::ReferenceScan ref(scans[i], plicp);
    bool consecutive_seen = false;
    for (; k < pairs.size() && pairs[k].first == i; ++k)
    {
      consecutive_seen |= pairs[k].second == i + 1;
      match(i, pairs[k].second, ref);
    }
    if (!consecutive_seen) match(i, i + 1, ref);
  }
  result.edges = problem.edges.size();
  const Eigen::Vector3d weak(1 / (options.failed_sigma_xy * options.failed_sigma_xy),
                             1 / (options.failed_sigma_xy * options.failed_sigma_xy),
                             1 / (options.failed_sigma_theta * options.failed_sigma_theta));
  for (size_t j = 1; j < scans.size(); ++j)
    if (!consecutive_linked[j])
    {
      result.failed_consecutive++;
      problem.edges.push_back({static_cast<int>(j - 1), static_cast<int>(j),
                               asVector(sensor_poses[j] - sensor_poses[j - 1]), weak.asDiagonal(),
                               graph.isRobust(graph::EdgeKind::OdometryPrior)});
    }
  result.report = graph::optimizeGraphProblem(problem, graph);
  for (const auto& p : problem.poses) result.optimum.emplace_back(p.x(), p.y(), p.z());
  return result;
}

std::string laserOptimumReport(const std::string& log_path, const std::vector<common::StampedPose>& trajectory,
                               const plicp::PlicpParams& plicp, const graph::GraphOptimizerParams& graph,
                               const LaserOptimumOptions& options, double max_dt, size_t stride,
                               double min_range, const io::CarmenParams& carmen,
                               const std::string& sensor_label, const std::string& output)
{
  const auto posed = loadPosedScans(log_path, {trajectory}, max_dt, stride, min_range, carmen, sensor_label);
  const auto& given = posed.sensor_poses[0];
  const auto r = laserOptimum(posed.scans, given, plicp, graph, options);
  std::vector<PosePair> moved;
  for (size_t k = 0; k < given.size(); ++k) moved.push_back({0, 0, r.optimum[k], given[k]});
  // Poses left as given by an optimizer that failed are no optimum.
  if (r.report.status != graph::OptimizationStatus::Converged &&
      r.report.status != graph::OptimizationStatus::MaxIterations)
    throw std::runtime_error(std::string("laser optimum: the optimizer stopped with status ") +
                             graph::statusName(r.report.status) + " (" + r.report.message +
                             "): no optimum");
  const auto distance = absoluteTrajectoryError(moved).position;
  if (!output.empty())
  {
    std::vector<common::StampedPose> vehicle;
    for (size_t k = 0; k < given.size(); ++k)
      vehicle.push_back({mrpt::Clock::toDouble(posed.scans[k].timestamp),
                         r.optimum[k] + (CPose2D() - posed.scans[k].sensor_pose)});  // (+) mount^-1
    common::writeTum(output, vehicle);
  }
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "scans=%zu\nlog_scans=%zu\nunposed_scans=%zu\npairs=%zu\nedges=%zu\n"
                "failed_consecutive=%zu\nstatus=%s\niterations=%zu\nmoved_rmse_m=%.6g\n"
                "moved_median_m=%.6g\nmoved_max_m=%.6g\n"
                "# the scans' own optimum lies %.4f m (rmse) from the trajectory: %zu edges of %zu "
                "pairs, %zu consecutive without a match, optimizer %s\n",
                posed.scans.size(), posed.log_scans, posed.unposed, r.pairs, r.edges,
                r.failed_consecutive, graph::statusName(r.report.status), r.report.iterations,
                distance.rmse, distance.median, distance.max, distance.rmse,
                r.edges, r.pairs, r.failed_consecutive, graph::statusName(r.report.status));
  return buf;
}

}  // namespace swslam::eval
