#pragma once
// The whole SLAM system (paper Fig. 1): local tracking, graph optimization and map
// construction. Threaded mode runs each module on its own named thread that owns its input
// queue (scans -> tracking -> graph -> map); deterministic mode runs the very same steps on
// the caller's thread in a fixed order, so two runs give bit-identical results.
//
// feed() checks each scan where it enters, on the caller's thread (input_gate.h). A module
// that fails, in either mode, stops the pipeline; error() says which and why, and results()
// still holds everything processed until then (run_recorder.h).

#include <swslam/system/backlog.h>
#include <swslam/system/blocking_queue.h>
#include <swslam/system/config.h>
#include <swslam/system/graph_module.h>
#include <swslam/system/input_gate.h>
#include <swslam/system/map_module.h>
#include <swslam/system/messages.h>
#include <swslam/system/run_recorder.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace swslam::system
{
/** A saved session to continue (app/session.h reads one): its graph, nodes 0..n-1, and each
 * node's observation, as the session's run fed it. */
struct ResumedSession
{
  graph::PoseGraph graph;
  std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> observations;  ///< by node id
};

enum class RunMode
{
  Threaded,       ///< three module threads (live use; the default)
  Deterministic,  ///< the same steps on the caller's thread, in a fixed order
};

class SlamSystem
{
 public:
  SlamSystem(const SystemParams& params, RunMode mode);
  ~SlamSystem();
  SlamSystem(const SlamSystem&) = delete;
  SlamSystem& operator=(const SlamSystem&) = delete;

  /** Continues `session` (before the first scan): its nodes become the graph's and the map's,
   * its last nodes tracking's keyframes; new nodes take the next ids, and loops between the
   * session's nodes and the new ones close as any loop. Throws std::logic_error after a scan,
   * std::invalid_argument naming a node whose observation is missing or fails the input's
   * geometry check, or a graph that does not fit the observations. */
  void resume(const ResumedSession& session);

  /** Processes one scan (threaded: queues it, waiting while the queue is full). */
  FeedResult feed(sensor::ScanInput input);

  /** No more input: drains every queue, runs the final full optimization and the final
   * refinement (each if configured; the refinement only with `refine`: a run stopped by a
   * signal ends sooner without its matches), joins the threads. Idempotent. */
  void finish(bool refine = true);

  /** Empty unless a module failed. */
  std::string error() const;
  SystemStatus status() const;
  RunResults results() const;
  /** A copy of the current occupancy grid (any time, any thread). */
  mrpt::maps::COccupancyGridMap2D mapSnapshot() const;
  const SystemParams& params() const { return params_; }

 private:
  void trackOne(const sensor::ScanInput& input, size_t index);
  void graphOne(const NewNode& node);
  void mapOne(const MapMessage& message);
  /** A graph step's poses to tracking's mailbox and its inserts to the map. */
  void applyGraphStep(const GraphStep& step, double seconds);
  /** After the input ended (graph thread joined): `run(last scan index)` on this thread,
   * then its poses to tracking's mailbox and the map; a throw fails `module`. */
  void finalGraphStep(const char* module, const std::function<GraphStep(size_t)>& run);
  void trackingLoop();
  void graphLoop();
  void mapLoop();
  void fail(const std::string& module, const std::string& what);
  /** Deterministic mode: runs one module's step on this thread; a throw fails `module`
   * (as its thread's loop does in threaded mode). False if it failed. */
  bool guarded(const char* module, const std::function<void()>& step);
  void closeAll();

  const SystemParams params_;
  const RunMode mode_;
  tracking::LocalTracker tracker_;  ///< tracking thread only
  GraphModule graph_;
  MapModule map_;
  RunRecorder recorder_;

  BlockingQueue<std::pair<size_t, sensor::ScanInput>> scan_queue_;
  BlockingQueue<NewNode> node_queue_;
  BlockingQueue<MapMessage> map_queue_;
  Backlog graph_backlog_;  ///< keyframes sent to the graph thread and not finished
  std::thread tracking_thread_, graph_thread_, map_thread_;

  mutable std::mutex updates_mutex_;
  PoseUpdate pending_updates_;  ///< graph -> tracking mailbox, guarded by updates_mutex_

  // feed()'s state: the caller's thread only.
  InputGate gate_;
  size_t fed_ = 0;
  bool finished_ = false;
};

}  // namespace swslam::system
