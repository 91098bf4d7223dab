#include <swslam/system/slam_system.h>

#include <swslam/sensor/scan.h>

#include <chrono>
#include <cmath>
#include <pthread.h>
#include <stdexcept>
#include <string>

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
}  // namespace

SlamSystem::SlamSystem(const SystemParams& params, RunMode mode)
    : params_(params),
      mode_(mode),
      tracker_(params.tracking, params.plicp, params.correlative),
      graph_(params.graph_optimizer, params.loop_closure, params.plicp, params.correlative),
      map_(params.map),
      recorder_(tracking::PlacementModel{params.tracking.placement_acceleration,
                                         params.tracking.placement_angular_acceleration}),
      scan_queue_(static_cast<size_t>(params.system.input_queue_capacity)),
      gate_(params.system)
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

void SlamSystem::resume(const ResumedSession& session)
{
  if (fed_ > 0 || finished_) throw std::logic_error("slam: a session is resumed before the first scan");
  const size_t n = session.graph.nodeCount();
  if (n == 0 || session.observations.size() != n)
    throw std::invalid_argument("slam: a resumed session has " + std::to_string(n) + " graph nodes and " +
                                std::to_string(session.observations.size()) + " node observations");
  std::vector<mrpt::poses::CPose2D> poses;
  std::vector<std::shared_ptr<const plicp::ReferenceScan>> scans;
  std::vector<double> times;
  for (size_t id = 0; id < n; id++)
  {
    const auto& obs = session.observations[id];
    if (!obs) throw std::invalid_argument("slam: resumed node " + std::to_string(id) + " has no observation");
    if (!session.graph.hasNode(id))
      throw std::invalid_argument("slam: a resumed session's graph has no node " + std::to_string(id));
    try
    {
      sensor::checkObservationGeometry(*obs);
    }
    catch (const std::invalid_argument& e)
    {
      throw std::invalid_argument("slam: resumed node " + std::to_string(id) + "'s observation: " + e.what());
    }
    poses.push_back(session.graph.pose(id));
    scans.push_back(session.graph.isMerged(id)
                        ? nullptr  // never matched by the graph module again
                        : std::make_shared<const plicp::ReferenceScan>(
                              sensor::scanFromCheckedObservation(*obs, params_.tracking.min_range), params_.plicp));
    times.push_back(mrpt::Clock::toDouble(obs->timestamp));
  }
  graph_.restore(session.graph, scans);
  tracker_.resume(poses, session.observations);
  for (size_t id = 0; id < n; id++)
    if (!session.graph.isMerged(id)) map_.handle(MapInsert{0, id, session.observations[id], poses[id]});
  recorder_.resumed(times);
}

FeedResult SlamSystem::feed(sensor::ScanInput input)
{
  if (finished_ || !error().empty()) return {FeedStatus::Stopped, "the system has stopped"};
  const FeedResult result = gate_.admit(input);
  if (!result.ok())
  {
    recorder_.skipped();
    return result;
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
  recorder_.tracked(index, mrpt::Clock::toDouble(input.observation->timestamp), step, secondsSince(t0),
                    tracker_.keyframes().size());
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
  recorder_.graphed(step, seconds);
  auto toMap = [this](MapMessage m) {
    if (mode_ == RunMode::Deterministic)
      guarded("map construction", [&] { mapOne(m); });
    else
      map_queue_.push(std::move(m));
  };
  if (step.insert) toMap(*step.insert);
  if (!step.reinsert.poses.empty() || !step.reinsert.removed.empty()) toMap(step.reinsert);
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
  recorder_.mapped(step.scan, secondsSince(t0));
}

void SlamSystem::fail(const std::string& module, const std::string& what)
{
  recorder_.fail(module, what);
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
    const size_t last_scan = recorder_.lastScan();
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

std::string SlamSystem::error() const { return recorder_.error(); }

SystemStatus SlamSystem::status() const
{
  SystemStatus s = recorder_.status();
  s.queued = scan_queue_.size();
  return s;
}

RunResults SlamSystem::results() const
{
  return recorder_.results(graph_.graphCopy(), graph_.loopCount(), map_.builder().bytes());
}

mrpt::maps::COccupancyGridMap2D SlamSystem::mapSnapshot() const { return map_.builder().snapshot(); }

}  // namespace swslam::system
