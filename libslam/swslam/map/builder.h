#pragma once
// Map construction (paper sec. IV, Fig. 1): the occupancy grid built from the nodes' scans,
// where a node whose pose changes has its old contribution removed exactly before its scan
// is inserted at the new pose. A node keeps its scan and pose only: its contribution is traced
// again when it must be removed, so that memory per node is its scan's.
//
// Threading: one thread (the map thread) calls the mutating methods; any thread may call
// snapshot() and the const accessors. Writers are serialized by write_mutex_; the grid is
// guarded by grid_mutex_, held only while contributions are applied (the ray tracing runs
// before), so readers wait at most for one apply step and always see whole updates.

#include <swslam/map/params.h>
#include <swslam/map/scan_contribution.h>
#include <swslam/map/stored_scan.h>
#include <swslam/map/summed_grid.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <map>
#include <mutex>

namespace swslam::map
{
using MapNodeId = uint64_t;

/** What reinsertMoved() did. */
struct ReinsertReport
{
  size_t moved = 0;      ///< nodes re-inserted
  size_t unchanged = 0;  ///< nodes within the threshold
  size_t unknown = 0;    ///< poses given for nodes the map does not hold
};

class MapBuilder
{
 public:
  explicit MapBuilder(const MapParams& params);

  /** Inserts node `id`'s scan seen from `vehicle_pose` (eq. 15-16). Throws
   * std::invalid_argument if `id` is already in the map or the scan cannot be inserted. */
  void insert(MapNodeId id, const mrpt::obs::CObservation2DRangeScan& scan,
              const mrpt::poses::CPose2D& vehicle_pose);

  /** Moves node `id` to `new_pose`: subtracts its contribution, adds it at the new pose.
   * The grid is then identical to one where the node was inserted at `new_pose` directly.
   * Throws std::invalid_argument for an unknown node. */
  void update(MapNodeId id, const mrpt::poses::CPose2D& new_pose);

  /** Removes node `id`'s contribution and forgets it. Throws for an unknown node. */
  void remove(MapNodeId id);

  /** After an optimization (sec. IV.B): updates the nodes of `poses` that moved more than
   * `threshold` from the pose they were inserted at; all changes appear to readers at once. */
  ReinsertReport reinsertMoved(const std::map<MapNodeId, mrpt::poses::CPose2D>& poses,
                               const geometry::MoveThreshold& threshold);

  /** A copy of the current grid, safe to use while the map keeps changing. */
  mrpt::maps::COccupancyGridMap2D snapshot() const;

  /** Pose at which node `id`'s scan is in the map. Throws for an unknown node. */
  mrpt::poses::CPose2D nodePose(MapNodeId id) const;
  size_t nodeCount() const;
  /** The exact (unclamped) log-odds sum of global cell (x, y), floor(world / resolution); 0
   * outside the grid. */
  int32_t cellSum(int x, int y) const;
  /** The grid's cells, global. */
  CellBox cellBox() const;
  /** Memory held by the grid, the sums and the nodes' scans [bytes]. */
  size_t bytes() const;

  const MapParams& params() const { return params_; }

 private:
  struct Node
  {
    StoredScan scan;                          ///< sanitized copy
    mrpt::poses::CPose2D pose;                ///< where its contribution is in the sums
  };

  const MapParams params_;
  mutable std::mutex write_mutex_;
  std::map<MapNodeId, Node> nodes_;  ///< guarded by write_mutex_
  ContributionScratch scratch_;      ///< guarded by write_mutex_
  mutable std::mutex grid_mutex_;
  SummedGrid grid_;                  ///< guarded by grid_mutex_
};

}  // namespace swslam::map
