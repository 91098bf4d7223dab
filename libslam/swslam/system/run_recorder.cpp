#include <swslam/system/run_recorder.h>

namespace swslam::system
{
void RunRecorder::resumed(const std::vector<double>& node_times)
{
  std::lock_guard<std::mutex> lock(mutex_);
  keyframe_times_ = node_times;
  status_.nodes = node_times.size();
}

void RunRecorder::skipped()
{
  std::lock_guard<std::mutex> lock(mutex_);
  status_.skipped++;
}

void RunRecorder::tracked(size_t index, double timestamp, const tracking::TrackingStep& step, double seconds,
                          size_t nodes)
{
  ScanStats row;
  row.scan = index;
  row.timestamp = timestamp;
  row.source = step.source;
  row.valid_rays = step.valid_rays;
  row.correspondences = step.match.correspondences;
  row.match_sq_residuals = step.match.sum_sq_residuals;
  row.match_ms = 1e3 * step.match_time;
  row.tracking_ms = 1e3 * seconds;
  row.keyframe = step.keyframe;
  row.new_node = step.new_keyframe;
  row.ambiguous = step.ambiguous;
  row.prior_decided = step.prior_decided;
  std::lock_guard<std::mutex> lock(mutex_);
  stats_.push_back(row);
  const Eigen::Matrix3d& info = step.relative_information;
  trajectory_.push_back({row.timestamp, step.keyframe, step.relative.asTPose(), step.pose.asTPose(),
                         {float(info(0, 0)), float(info(0, 1)), float(info(0, 2)), float(info(1, 1)),
                          float(info(1, 2)), float(info(2, 2))}});
  if (step.new_keyframe) keyframe_times_.push_back(row.timestamp);
  status_.scans++;
  status_.nodes = nodes;
  if (tracking::isFallback(step.source)) status_.fallbacks++;
  status_.last_source = step.source;
  status_.last_match = step.match.status;
  status_.last_correspondences = step.match.correspondences;
  status_.last_valid_rays = step.valid_rays;
}

void RunRecorder::graphed(const GraphStep& step, double seconds)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (step.scan < stats_.size())
  {
    ScanStats& row = stats_[step.scan];
    row.graph_ms += 1e3 * seconds;
    // A step that optimized nothing (e.g. a final refinement that added no edge) keeps the
    // row's residuals: Fig. 7's curve carries the last optimization's.
    if (step.report.status != graph::OptimizationStatus::NothingToOptimize)
    {
      row.active_sq_residuals = step.report.active_sq_residuals;
      row.switched_off = step.report.switched_off.size();
    }
    // The whole graph's latest optimization says which edges the kernel distrusts.
    if (step.full && step.report.status != graph::OptimizationStatus::NothingToOptimize &&
        step.report.status != graph::OptimizationStatus::Diverged)
      switched_off_ = step.report.switched_off;
    row.loops += step.loops_accepted;
    row.full_optimization = row.full_optimization || step.full;
  }
  status_.loops += step.loops_accepted;
  status_.refinement_pairs += step.pairs_refined;
  status_.refinement_edges += step.refinement_edges;
}

void RunRecorder::mapped(size_t scan, double seconds)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (scan < stats_.size()) stats_[scan].map_ms += 1e3 * seconds;
}

void RunRecorder::fail(const std::string& module, const std::string& what)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (error_.empty()) error_ = module + ": " + what;
}

std::string RunRecorder::error() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

SystemStatus RunRecorder::status() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

size_t RunRecorder::lastScan() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_.empty() ? 0 : stats_.size() - 1;
}

RunResults RunRecorder::results(graph::PoseGraph graph, size_t loops, size_t map_bytes) const
{
  RunResults r;
  r.graph = std::move(graph);
  r.loops = loops;
  r.map_bytes = map_bytes;
  std::lock_guard<std::mutex> lock(mutex_);
  r.stats = stats_;
  r.skipped = status_.skipped;
  r.refinement_pairs = status_.refinement_pairs;
  r.refinement_edges = status_.refinement_edges;
  r.switched_off = switched_off_;
  // Rows without an optimization carry the last one's residuals (Fig. 7 is a curve).
  double active = 0;
  for (ScanStats& row : r.stats)
  {
    if (row.graph_ms > 0) active = row.active_sq_residuals;
    row.active_sq_residuals = active;
  }
  r.trajectory.reserve(trajectory_.size());
  for (const TrajectoryRecord& rec : trajectory_) r.trajectory.push_back({rec.t, place(rec, r.graph)});
  r.keyframes.reserve(keyframe_times_.size());
  for (size_t id = 0; id < keyframe_times_.size(); ++id)
    if (r.graph.hasNode(id)) r.keyframes.push_back({keyframe_times_[id], r.graph.pose(id)});
  return r;
}

mrpt::poses::CPose2D RunRecorder::place(const TrajectoryRecord& rec, const graph::PoseGraph& graph) const
{
  using mrpt::poses::CPose2D;
  // A keyframe the graph has not received yet (threaded, mid-run): the tracked pose.
  if (!graph.hasNode(rec.keyframe)) return CPose2D(rec.tracked);
  const CPose2D a = graph.pose(rec.keyframe);
  const size_t next = rec.keyframe + 1;
  // After the last keyframe, or before one the graph has not received yet: the match alone. (A
  // merged node keeps a pose, on its anchor.)
  if (next >= keyframe_times_.size() || !graph.hasNode(next)) return a + CPose2D(rec.relative);
  const std::array<float, 6>& u = rec.information;
  Eigen::Matrix3d info;
  info << u[0], u[1], u[2], u[1], u[3], u[4], u[2], u[4], u[5];
  const double t0 = keyframe_times_[rec.keyframe];
  return a + tracking::placeBetweenKeyframes(graph.pose(next) - a, rec.t - t0, keyframe_times_[next] - t0,
                                             CPose2D(rec.relative), info, placement_);
}

}  // namespace swslam::system
