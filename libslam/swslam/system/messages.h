#pragma once
// What the three module threads (paper Fig. 1) pass each other. Every message carries the
// index of the input scan whose processing caused it, so that each thread's time is
// attributed to that scan in stats.csv.

#include <swslam/map/builder.h>
#include <swslam/sensor/scan_input.h>
#include <swslam/tracking/local_tracker.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <map>
#include <optional>
#include <variant>
#include <vector>

namespace swslam::system
{
/** Tracking -> graph: a keyframe was made. */
struct NewNode
{
  size_t scan = 0;
  tracking::Keyframe keyframe;  ///< pose as tracked (the graph re-bases it on its own estimate)
  mrpt::obs::CObservation2DRangeScan::Ptr observation;
  std::vector<graph::Constraint> edges;  ///< edges[0] connects the previous node
};

/** Graph -> map: insert a new node's scan. */
struct MapInsert
{
  size_t scan = 0;
  map::MapNodeId id = 0;
  mrpt::obs::CObservation2DRangeScan::Ptr observation;
  mrpt::poses::CPose2D pose;
};

/** Graph -> map: nodes merged into others (their scans leave the map), then node poses after
 * an optimization (moved ones get re-inserted). */
struct MapReinsert
{
  size_t scan = 0;
  std::vector<map::MapNodeId> removed;
  std::map<map::MapNodeId, mrpt::poses::CPose2D> poses;
};

using MapMessage = std::variant<MapInsert, MapReinsert>;

/** Graph -> tracking: optimized keyframe poses. */
using PoseUpdate = std::map<size_t, mrpt::poses::CPose2D>;

}  // namespace swslam::system
