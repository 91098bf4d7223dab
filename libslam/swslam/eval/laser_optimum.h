#pragma once
// How far the scans' own constraints pull a trajectory: every pair of scans close at the
// trajectory's poses is matched by PLICP from the trajectory's relative pose, and the graph of
// those matches is optimized starting at the trajectory. A trajectory the laser data supports
// is (close to) an optimum of that graph and hardly moves; a reference made with other
// sensors (odometry), or in a place the laser data leaves open, moves by what the scans
// disagree with. No tracking decision is involved: only the trajectory given and the scans.

#include <swslam/common/tum_io.h>
#include <swslam/graph/optimizer.h>
#include <swslam/io/carmen_log.h>
#include <swslam/loop/params.h>
#include <swslam/plicp/plicp.h>
#include <swslam/sensor/scan.h>
#include <swslam/tracking/params.h>

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <string>
#include <vector>

namespace swslam::eval
{
struct LaserOptimumOptions
{
  double radius = 4.0;               ///< [m] pairs of sensor poses this close ([tracking] dense_radius)
  size_t dense_max_index_gap = 30;   ///< pairs up to this many scans apart weigh as dense edges, farther as loops
  double gate_xy = 0.3;              ///< [m] a match moving the trajectory's relative pose more...
  double gate_theta = 5 * M_PI / 180;  ///< [rad] ...or turning it more is dropped ([tracking] dense_gate_*)
  double min_inlier_fraction = 0.3;  ///< of the newer scan's valid rays ([loop_closure])
  double failed_sigma_xy = 1.0;      ///< [m] a failed consecutive match: a weak edge on the
  double failed_sigma_theta = 10 * M_PI / 180;  ///< trajectory's own step ([tracking] lost_prior_sigma_*)
};

/** The options a run's configuration implies: [tracking] dense_radius, dense_max_index_gap,
 * dense_gate_xy / _theta, lost_prior_sigma_xy / _theta and [loop_closure] min_inlier_fraction. */
LaserOptimumOptions laserOptimumOptions(const tracking::TrackingParams& tracking, const loop::LoopClosureParams& loops);

struct LaserOptimumResult
{
  size_t pairs = 0;               ///< pairs matched (consecutive scans always)
  size_t edges = 0;               ///< of them, kept as edges
  size_t failed_consecutive = 0;  ///< consecutive pairs whose match failed or was gated (weak edges)
  graph::OptimizationReport report;
  std::vector<mrpt::poses::CPose2D> optimum;  ///< sensor poses after optimization
};

/** Matches every pair (i, j), i < j, of `scans` whose `sensor_poses` are within `radius` (and
 * every consecutive pair) by PLICP from the relative pose sensor_poses[i]^-1 (+) sensor_poses[j].
 * A match is an edge if it converged (or hit the iteration cap), pairs at least
 * min_inlier_fraction of the newer scan's valid rays and stays within the gate of its guess;
 * its information is the inverse of the PLICP covariance, robustified as `graph` says for its
 * kind (consecutive; dense up to dense_max_index_gap scans apart; loop beyond). A consecutive
 * pair without such a match gets a weak edge on the given step, so the graph stays connected.
 * The graph is optimized from `sensor_poses` with the first pose held. Throws
 * std::invalid_argument if the sizes differ or fewer than two scans are given. */
LaserOptimumResult laserOptimum(const std::vector<sensor::Scan>& scans,
                                const std::vector<mrpt::poses::CPose2D>& sensor_poses,
                                const plicp::PlicpParams& plicp, const graph::GraphOptimizerParams& graph,
                                const LaserOptimumOptions& options);

/** What `swslam-eval laser-optimum` prints: reads the log's scans at the trajectory's poses
 * (loadPosedScans(), every `stride`-th: a 40 Hz log has hundreds of scans within the radius
 * of each other), runs laserOptimum() and gives the counts, the optimizer's report and the
 * ATE of the optimum against the trajectory (SE(2)-aligned sensor positions: how far the
 * scans pull it). With `output` non-empty, also writes the optimum there as a TUM trajectory
 * of vehicle poses (each sensor pose composed with the inverse of its scan's mounting) at the
 * scans' timestamps. Throws std::runtime_error naming the problem when the log cannot be read,
 * fewer than two scans have a pose, or the optimizer fails (no optimum, nothing written). */
std::string laserOptimumReport(const std::string& log_path, const std::vector<common::StampedPose>& trajectory,
                               const plicp::PlicpParams& plicp, const graph::GraphOptimizerParams& graph,
                               const LaserOptimumOptions& options, double max_dt, size_t stride,
                               double min_range, const io::CarmenParams& carmen,
                               const std::string& sensor_label = "", const std::string& output = "");

}  // namespace swslam::eval
