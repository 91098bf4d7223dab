#pragma once
// Rebuilds a finished run's occupancy map from its graph and its input log, e.g. at a finer
// resolution than the online map (the paper's offline 0.1 m map, Fig. 4).

#include <swslam/common/tum_io.h>
#include <swslam/graph/pose_graph.h>
#include <swslam/io/carmen_log.h>
#include <swslam/io/scan_source.h>
#include <swslam/map/params.h>
#include <swslam/system/scan_stats.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>
#include <vector>

namespace swslam::app
{
struct RegenReport
{
  size_t nodes = 0;     ///< graph nodes
  size_t inserted = 0;  ///< nodes whose scan was found in the log and inserted (not the merged ones)
};

/** Inserts, for each graph node, the log's scan stamped with that node's time in
 * `keyframes` (the run's keyframes.tum, node i on line i) at the node's graph pose; the log is
 * read with `scans` (the run's sensor and topics; odometry is not read). Throws
 * std::runtime_error naming the problem if the keyframes and the graph disagree, or if a
 * node's scan is missing from the log. */
mrpt::maps::COccupancyGridMap2D regenerateMap(const graph::PoseGraph& graph,
                                              const std::vector<common::StampedPose>& keyframes,
                                              const std::string& log_path, const map::MapParams& params,
                                              const io::CarmenParams& carmen, const io::ScanSourceOptions& scans,
                                              RegenReport* report = nullptr);

/** The run's stats.csv rows for its pictures (overlayOf marks the scans the prediction
 * placed), if there is one row per pose of its `trajectory_poses`-pose trajectory. Otherwise
 * none, and `problem` says why (a missing file leaves it empty: older runs have none). */
std::vector<system::ScanStats> statsForPictures(const std::string& stats_path, size_t trajectory_poses,
                                                std::string& problem);

}  // namespace swslam::app
