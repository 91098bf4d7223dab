#pragma once
// What a run produced, kept as the three modules report it (from their threads): a row of
// stats.csv per scan, each scan's place on its keyframe, the status line's counts, the
// latest full optimization's switched-off edges, and the first failure.

#include <swslam/common/tum_io.h>
#include <swslam/graph/pose_graph.h>
#include <swslam/system/graph_module.h>
#include <swslam/system/scan_stats.h>
#include <swslam/tracking/local_tracker.h>
#include <swslam/tracking/placement.h>

#include <mrpt/math/TPose2D.h>

#include <array>
#include <mutex>
#include <string>
#include <vector>

namespace swslam::system
{
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
  /** Every processed scan: a keyframe's pose, and each scan after it placed between it and
   * the next keyframe (tracking/placement.h). */
  std::vector<common::StampedPose> trajectory;
  std::vector<common::StampedPose> keyframes;   ///< graph node poses, stamped with their scan's time
  graph::PoseGraph graph;
  std::vector<ScanStats> stats;
  size_t skipped = 0, loops = 0;
  size_t refinement_pairs = 0, refinement_edges = 0;  ///< final refinement: pairs matched, edges added
  size_t map_bytes = 0;  ///< memory held by the map (grid, sums, per-node contributions)
  /** Edges (graph indices) the latest full optimization's kernel switched off. */
  std::vector<size_t> switched_off;
};

class RunRecorder
{
 public:
  /** Scans between keyframes are placed with `placement`. */
  explicit RunRecorder(const tracking::PlacementModel& placement) : placement_(placement) {}

  /** A resumed session's nodes, stamped (before any scan): keyframes.tum lists them first. */
  void resumed(const std::vector<double>& node_times);
  /** A scan skipped where it entered. */
  void skipped();
  /** Scan `index` (stamped `timestamp`), tracked in `seconds`; the tracker has `nodes` nodes. */
  void tracked(size_t index, double timestamp, const tracking::TrackingStep& step, double seconds, size_t nodes);
  /** A graph step, charged to its scan. */
  void graphed(const GraphStep& step, double seconds);
  /** The map's work for scan `scan`. */
  void mapped(size_t scan, double seconds);
  /** A module failed: the first failure is the run's error. */
  void fail(const std::string& module, const std::string& what);

  std::string error() const;  ///< empty unless a module failed
  SystemStatus status() const;
  size_t lastScan() const;  ///< the index of the last scan tracked (0 before any)
  /** The results, with every scan placed on `graph`'s optimized keyframes. */
  RunResults results(graph::PoseGraph graph, size_t loops, size_t map_bytes) const;

 private:
  /** One per scan, for the whole run: plain poses (24 bytes, against CPose2D's 64). */
  struct TrajectoryRecord
  {
    double t;
    size_t keyframe;
    mrpt::math::TPose2D relative;
    mrpt::math::TPose2D tracked;  ///< the pose tracking gave it at the time
    /** The upper triangle of the information of `relative` (row by row; zero: no match). */
    std::array<float, 6> information;
  };
  /** Where `rec` lies on `graph`'s optimized keyframes. */
  mrpt::poses::CPose2D place(const TrajectoryRecord& rec, const graph::PoseGraph& graph) const;

  const tracking::PlacementModel placement_;

  mutable std::mutex mutex_;
  std::vector<ScanStats> stats_;              ///< by scan index, guarded by mutex_
  std::vector<TrajectoryRecord> trajectory_;  ///< guarded by mutex_
  std::vector<double> keyframe_times_;        ///< guarded by mutex_
  SystemStatus status_;                       ///< guarded by mutex_
  std::string error_;                         ///< guarded by mutex_
  std::vector<size_t> switched_off_;          ///< the latest full optimization's; guarded by mutex_
};

}  // namespace swslam::system
