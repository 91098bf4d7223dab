#pragma once
// The whole SLAM system (paper Fig. 1): local tracking, graph optimization and map
// construction. Threaded mode runs each module on its own named thread that owns its input
// queue (scans -> tracking -> graph -> map); deterministic mode runs the very same steps on
// the caller's thread in a fixed order, so two runs give bit-identical results.
//
// feed() validates each scan on the caller's thread: a timestamp that does not increase
// (backwards or duplicated) or inconsistent geometry skips the scan and says why; an
// odometry increment that is not finite is dropped (the scan is tracked without it) and
// said. A module that fails, in either mode, stops the pipeline; error() says which and
// why, and results() still holds everything processed until then.

#include <swslam/common/tum_io.h>
#include <swslam/graph/pose_graph.h>
#include <swslam/system/backlog.h>
#include <swslam/system/blocking_queue.h>
#include <swslam/system/config.h>
#include <swslam/system/graph_module.h>
#include <swslam/system/map_module.h>
#include <swslam/system/messages.h>
#include <swslam/system/scan_stats.h>

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
enum class RunMode
{
  Threaded,       ///< three module threads (live use; the default)
  Deterministic,  ///< the same steps on the caller's thread, in a fixed order
};

/** Why feed() did not take a scan. */
enum class FeedStatus
{
  Accepted,
  TimestampNotIncreasing,  ///< backwards or duplicated: skipped
  TimestampOutOfRange,     ///< not in 1970-2200 (common/unix_time.h), e.g. in microseconds: skipped
  BadGeometry,             ///< too few beams, aperture, max range or sensor pose unusable: skipped
  OdometryDropped,         ///< taken, without its odometry increment (not finite, or too long)
  TimestampsResumed,       ///< taken: the scans behind a stamp that jumped forward resume the log
  Stopped,                 ///< the pipeline stopped (finish() was called or a module failed)
};
/** The scan was taken (possibly without its odometry), not skipped. */
inline bool scanTaken(FeedStatus s)
{
  return s == FeedStatus::Accepted || s == FeedStatus::OdometryDropped || s == FeedStatus::TimestampsResumed;
}

struct FeedResult
{
  FeedStatus status = FeedStatus::Accepted;
  std::string message;  ///< what was wrong: why a scan was skipped, or what of it was dropped
  /** The scan was taken (possibly without its odometry). */
  bool ok() const { return scanTaken(status); }
};

/** A live summary (status line). */
struct SystemStatus
{
  size_t scans = 0, skipped = 0, nodes = 0, loops = 0, fallbacks = 0;
  size_t refinement_pairs = 0, refinement_edges = 0;  ///< final refinement: pairs matched, edges added
  size_t queued = 0;  ///< scans waiting for tracking
  tracking::TrackingSource last_source = tracking::TrackingSource::First;
  plicp::MatchStatus last_match = plicp::MatchStatus::InvalidInput;
  size_t last_correspondences = 0, last_valid_rays = 0;
};

/** Everything a run produced (copies, safe to use while the system keeps running). */
struct RunResults
{
  std::vector<common::StampedPose> trajectory;  ///< every processed scan: keyframe pose (+) relative
  std::vector<common::StampedPose> keyframes;   ///< graph node poses, stamped with their scan's time
  graph::PoseGraph graph;
  std::vector<ScanStats> stats;
  size_t skipped = 0, loops = 0;
  size_t refinement_pairs = 0, refinement_edges = 0;  ///< final refinement: pairs matched, edges added
  size_t map_bytes = 0;  ///< memory held by the map (grid, sums, per-node contributions)
  /** Edges (graph indices) the latest full optimization's kernel switched off. */
  std::vector<size_t> switched_off;
};

class SlamSystem
{
 public:
  SlamSystem(const SystemParams& params, RunMode mode);
  ~SlamSystem();
  SlamSystem(const SlamSystem&) = delete;
  SlamSystem& operator=(const SlamSystem&) = delete;

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
  struct TrajectoryRecord
  {
    double t;
    size_t keyframe;
    mrpt::poses::CPose2D relative;
    mrpt::poses::CPose2D tracked;  ///< the pose tracking gave it at the time
  };

  void trackOne(const sensor::ScanInput& input, size_t index);
  void graphOne(const NewNode& node);
  void mapOne(const MapMessage& message);
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

  BlockingQueue<std::pair<size_t, sensor::ScanInput>> scan_queue_;
  BlockingQueue<NewNode> node_queue_;
  BlockingQueue<MapMessage> map_queue_;
  Backlog graph_backlog_;  ///< keyframes sent to the graph thread and not finished
  std::thread tracking_thread_, graph_thread_, map_thread_;

  mutable std::mutex updates_mutex_;
  PoseUpdate pending_updates_;  ///< graph -> tracking mailbox, guarded by updates_mutex_

  mutable std::mutex results_mutex_;
  std::vector<ScanStats> stats_;               ///< by scan index, guarded by results_mutex_
  std::vector<TrajectoryRecord> trajectory_;   ///< guarded by results_mutex_
  std::vector<double> keyframe_times_;         ///< guarded by results_mutex_
  SystemStatus status_;                        ///< guarded by results_mutex_
  std::string error_;                          ///< guarded by results_mutex_
  std::vector<size_t> switched_off_;           ///< the latest full optimization's; guarded by results_mutex_

  // feed()'s state: the caller's thread only.
  size_t fed_ = 0;
  double last_timestamp_ = -1;
  size_t behind_in_order_ = 0;  ///< skipped scans in a row behind last_timestamp_, in order
  double last_behind_ = 0;      ///< the last of them's timestamp
  bool finished_ = false;
};

}  // namespace swslam::system
