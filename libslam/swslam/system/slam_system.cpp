#include <swslam/system/slam_system.h>

#include <swslam/common/unix_time.h>
#include <swslam/sensor/scan.h>

#include <mrpt/system/os.h>

#include <chrono>
#include <cmath>
#include <pthread.h>

namespace swslam::system
{
using mrpt::poses::CPose2D;

namespace
{
double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void nameThisThread(const char* name) { pthread_setname_np(pthread_self(), name); }

bool isFinite(const CPose2D& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.phi()); }
}  // namespace

SlamSystem::SlamSystem(const SystemParams& params, RunMode mode)
    : params_(params),
      mode_(mode),
      tracker_(params.tracking, params.plicp, params.correlative),
      graph_(params.graph_optimizer, params.loop_closure, params.plicp, params.correlative),
      map_(params.map),
      scan_queue_(static_cast<size_t>(params.system.input_queue_capacity))
{
  checkCrossSectionRules(params);
  if (mode_ == RunMode::Threaded)
  {
    tracking_thread_ = std::thread([this] { trackingLoop(); });
    graph_thread_ = std::thread([this] { graphLoop(); });
    map_thread_ = std::thread([this] { mapLoop(); });
  }
}

SlamSystem::~SlamSystem() { finish(); }

FeedResult SlamSystem::feed(sensor::ScanInput input)
{
  if (finished_ || !error().empty()) return {FeedStatus::Stopped, "the system has stopped"};
  auto skip = [&](FeedStatus s, const std::string& why) {
    std::lock_guard<std::mutex> lock(results_mutex_);
    status_.skipped++;
    return FeedResult{s, why};
  };
  if (!input.observation) return skip(FeedStatus::BadGeometry, "no observation");
  const double t = mrpt::Clock::toDouble(input.observation->timestamp);
  if (!common::plausibleUnixTime(t))
  {
    char buf[120];
    std::snprintf(buf, sizeof(buf), "timestamp %.6g s is outside 1970-2200", t);
    return skip(FeedStatus::TimestampOutOfRange, buf + common::timeUnitHint(t));
  }
  FeedResult result;
  if (!std::isfinite(t) || t <= last_timestamp_)
  {
    // Scans behind the last one taken, but in order among themselves: once there are
    // timestamp_resume_scans of them, that one had jumped forward and the log goes on here.
    const bool behind = std::isfinite(t) && t < last_timestamp_;
    behind_in_order_ = behind ? (behind_in_order_ > 0 && t > last_behind_ ? behind_in_order_ + 1 : 1) : 0;
    last_behind_ = t;
    const size_t resume = static_cast<size_t>(params_.system.timestamp_resume_scans);
    char buf[200];
    if (resume == 0 || behind_in_order_ < resume)
    {
      std::snprintf(buf, sizeof(buf), "timestamp %.6f s is %s the previous scan's (%.6f s)", t,
                    t == last_timestamp_ ? "equal to" : "before", last_timestamp_);
      return skip(FeedStatus::TimestampNotIncreasing, buf);
    }
    std::snprintf(buf, sizeof(buf),
                  "%zu scans in order behind %.6f s: that stamp jumped forward; the log resumes at %.6f s",
                  behind_in_order_, last_timestamp_, t);
    result = {FeedStatus::TimestampsResumed, buf};
  }
  behind_in_order_ = 0;
  try
  {
    sensor::checkObservationGeometry(*input.observation);
  }
  catch (const std::invalid_argument& e)
  {
    return skip(FeedStatus::BadGeometry, e.what());
  }
  // An odometry increment is checked where it enters: a value no vehicle reaches would become
  // the tracker's guess, the search's window and a map pose.
  const double since_last = t - last_timestamp_;
  last_timestamp_ = t;
  if (input.odometry_increment && !isFinite(*input.odometry_increment))
  {
    result = {FeedStatus::OdometryDropped,
              "odometry increment " + input.odometry_increment->asString() + " is not finite: ignored"};
    input.odometry_increment.reset();
  }
  else if (input.odometry_increment && params_.system.max_odometry_speed > 0 &&
           input.odometry_increment->norm() > params_.system.max_odometry_speed * std::max(since_last, 1.0))
  {
    char buf[240];
    std::snprintf(buf, sizeof(buf),
                  "odometry increment of %.6g m in %.3g s is beyond [system] max_odometry_speed (%g m/s): ignored",
                  input.odometry_increment->norm(), since_last, params_.system.max_odometry_speed);
    result = {FeedStatus::OdometryDropped, buf};
    input.odometry_increment.reset();
  }
  const size_t index = fed_++;
  if (mode_ == RunMode::Deterministic)
  {
    if (!guarded("tracking", [&] { trackOne(input, index); })) return {FeedStatus::Stopped, error()};
    return result;
  }
  if (!scan_queue_.push({index, std::move(input)})) return {FeedStatus::Stopped, "the system has stopped"};
  return result;
}

bool SlamSystem::guarded(const char* module, const std::function<void()>& step)
{
  try
  {
    step();
    return true;
  }
  catch (const std::exception& e)
  {
    fail(module, e.what());
    return false;
  }
}

void SlamSystem::trackOne(const sensor::ScanInput& input, size_t index)
{
  // Threaded: go on from the graph's optimized keyframes, as deterministic mode does, unless
  // more lag is allowed (the graph thread still optimizes while tracking waits for scans).
  if (mode_ == RunMode::Threaded && params_.system.max_graph_lag >= 0)
    graph_backlog_.waitAtMost(static_cast<size_t>(params_.system.max_graph_lag));
  {
    std::lock_guard<std::mutex> lock(updates_mutex_);
    for (const auto& [id, pose] : pending_updates_)
      if (id < tracker_.keyframes().size()) tracker_.setKeyframePose(id, pose);
    pending_updates_.clear();
  }
  const auto t0 = std::chrono::steady_clock::now();
  const tracking::TrackingStep step = tracker_.process(*input.observation, input.odometry_increment);
  const double seconds = secondsSince(t0);

  ScanStats row;
  row.scan = index;
  row.timestamp = mrpt::Clock::toDouble(input.observation->timestamp);
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
  {
    std::lock_guard<std::mutex> lock(results_mutex_);
    stats_.push_back(row);
    trajectory_.push_back({row.timestamp, step.keyframe, step.relative, step.pose});
    if (step.new_keyframe) keyframe_times_.push_back(row.timestamp);
    status_.scans++;
    status_.nodes = tracker_.keyframes().size();
    if (tracking::isFallback(step.source))
      status_.fallbacks++;
    status_.last_source = step.source;
    status_.last_match = step.match.status;
    status_.last_correspondences = step.match.correspondences;
    status_.last_valid_rays = step.valid_rays;
  }
  if (!step.new_keyframe) return;
  NewNode node;
  node.scan = index;
  node.keyframe = tracker_.keyframes().back();
  node.observation = input.observation;
  node.edges = step.edges;
  if (mode_ == RunMode::Deterministic)
    guarded("graph optimization", [&] { graphOne(node); });
  else
  {
    graph_backlog_.added();
    node_queue_.push(std::move(node));
  }
}

void SlamSystem::applyGraphStep(const GraphStep& step, double seconds)
{
  {
    std::lock_guard<std::mutex> lock(updates_mutex_);
    for (const auto& [id, pose] : step.poses) pending_updates_[id] = pose;
  }
  {
    std::lock_guard<std::mutex> lock(results_mutex_);
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
  auto toMap = [this](MapMessage m) {
    if (mode_ == RunMode::Deterministic)
      guarded("map construction", [&] { mapOne(m); });
    else
      map_queue_.push(std::move(m));
  };
  if (step.insert) toMap(*step.insert);
  if (!step.reinsert.poses.empty()) toMap(step.reinsert);
}

void SlamSystem::graphOne(const NewNode& node)
{
  const auto t0 = std::chrono::steady_clock::now();
  const GraphStep step = graph_.addNode(node);
  applyGraphStep(step, secondsSince(t0));
}

void SlamSystem::mapOne(const MapMessage& message)
{
  const auto t0 = std::chrono::steady_clock::now();
  const MapStep step = map_.handle(message);
  const double seconds = secondsSince(t0);
  std::lock_guard<std::mutex> lock(results_mutex_);
  if (step.scan < stats_.size()) stats_[step.scan].map_ms += 1e3 * seconds;
}

void SlamSystem::fail(const std::string& module, const std::string& what)
{
  {
    std::lock_guard<std::mutex> lock(results_mutex_);
    if (error_.empty()) error_ = module + ": " + what;
  }
  closeAll();
}

void SlamSystem::closeAll()
{
  scan_queue_.close();
  node_queue_.close();
  map_queue_.close();
  graph_backlog_.close();
}

void SlamSystem::trackingLoop()
{
  nameThisThread("swslam-track");
  try
  {
    while (auto item = scan_queue_.pop()) trackOne(item->second, item->first);
  }
  catch (const std::exception& e)
  {
    fail("tracking", e.what());
  }
  node_queue_.close();
}

void SlamSystem::graphLoop()
{
  nameThisThread("swslam-graph");
  try
  {
    while (auto node = node_queue_.pop())
    {
      graphOne(*node);
      graph_backlog_.done();
    }
  }
  catch (const std::exception& e)
  {
    fail("graph optimization", e.what());
  }
}

void SlamSystem::mapLoop()
{
  nameThisThread("swslam-map");
  try
  {
    std::vector<MapMessage> batch;
    while (auto first = map_queue_.pop())
    {
      // Everything waiting is taken at once: a map thread that fell behind re-inserts once
      // for consecutive optimizations.
      batch.clear();
      batch.push_back(std::move(*first));
      while (auto next = map_queue_.tryPop()) batch.push_back(std::move(*next));
      for (size_t i = 0; i < batch.size(); ++i)
      {
        auto* re = std::get_if<MapReinsert>(&batch[i]);
        while (re && i + 1 < batch.size() && std::holds_alternative<MapReinsert>(batch[i + 1]))
          MapModule::merge(*re, std::move(std::get<MapReinsert>(batch[++i])));
        mapOne(re ? MapMessage(std::move(*re)) : batch[i]);
      }
    }
  }
  catch (const std::exception& e)
  {
    fail("map construction", e.what());
  }
}

void SlamSystem::finalGraphStep(const char* module, const std::function<GraphStep(size_t)>& run)
{
  if (!error().empty()) return;
  try
  {
    size_t last_scan = 0;
    {
      std::lock_guard<std::mutex> lock(results_mutex_);
      last_scan = stats_.empty() ? 0 : stats_.size() - 1;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const GraphStep step = run(last_scan);
    applyGraphStep(step, secondsSince(t0));
  }
  catch (const std::exception& e)
  {
    fail(module, e.what());
  }
}

void SlamSystem::finish(bool refine)
{
  if (finished_) return;
  finished_ = true;
  if (mode_ == RunMode::Threaded)
  {
    scan_queue_.close();
    if (tracking_thread_.joinable()) tracking_thread_.join();  // closes node_queue_
    if (graph_thread_.joinable()) graph_thread_.join();
  }
  if (params_.system.final_full_optimization)
    finalGraphStep("final optimization", [this](size_t scan) { return graph_.optimizeAll(scan); });
  if (params_.final_refinement.enabled && refine)
    finalGraphStep("final refinement", [this](size_t scan) {
      return graph_.refineAll(scan, params_.final_refinement);
    });
  if (mode_ == RunMode::Threaded)
  {
    map_queue_.close();
    if (map_thread_.joinable()) map_thread_.join();
  }
  closeAll();
}

std::string SlamSystem::error() const
{
  std::lock_guard<std::mutex> lock(results_mutex_);
  return error_;
}

SystemStatus SlamSystem::status() const
{
  std::lock_guard<std::mutex> lock(results_mutex_);
  SystemStatus s = status_;
  s.queued = scan_queue_.size();
  return s;
}

RunResults SlamSystem::results() const
{
  RunResults r;
  r.graph = graph_.graphCopy();
  r.loops = graph_.loopCount();
  r.map_bytes = map_.builder().bytes();
  std::lock_guard<std::mutex> lock(results_mutex_);
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
  for (const TrajectoryRecord& rec : trajectory_)
  {
    // A keyframe the graph has not received yet (threaded, mid-run): the tracked pose.
    r.trajectory.push_back({rec.t, r.graph.hasNode(rec.keyframe)
                                       ? r.graph.pose(rec.keyframe) + rec.relative
                                       : rec.tracked});
  }
  for (size_t id = 0; id < keyframe_times_.size(); ++id)
    if (r.graph.hasNode(id)) r.keyframes.push_back({keyframe_times_[id], r.graph.pose(id)});
  return r;
}

mrpt::maps::COccupancyGridMap2D SlamSystem::mapSnapshot() const { return map_.builder().snapshot(); }

}  // namespace swslam::system
