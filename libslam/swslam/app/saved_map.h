#pragma once
// A finished map to localize on (swslam-localize --map): a session folder (session.h) or a
// swslam run folder. Either gives the nodes' optimized poses, their scans and the occupancy
// grid; a run folder's node scans are taken from its input log again, by stamp (as
// swslam-regen-map does), so the log must still be where its run.ini says.

#include <swslam/app/config.h>
#include <swslam/app/run_record.h>
#include <swslam/localize/map_nodes.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <string>
#include <vector>

namespace swslam::app
{
struct SavedMap
{
  bool session = false;  ///< a session folder (else a run folder)
  RunRecord record;      ///< how the map's run was made (its configuration is the localization's)
  std::vector<mrpt::poses::CPose2D> poses;  ///< node i's optimized vehicle pose
  std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> observations;  ///< node i's scan
  mrpt::maps::COccupancyGridMap2D grid;     ///< map.gridmap.gz
};

/** Reads the map in `dir`: a session if it holds session.ini, else a run folder (run.ini,
 * graph.graph, keyframes.tum, map.gridmap.gz). Throws std::invalid_argument naming the folder,
 * the file and the problem (missing, damaged, counts that disagree, a node whose scan the log
 * does not hold). */
SavedMap readSavedMap(const std::string& dir);

/** The map's nodes for localization, their scans read with `config`'s [tracking] min_range.
 * Throws std::invalid_argument naming a node whose scan fails the input's geometry check, or
 * as localize::MapNodes does. */
std::unique_ptr<localize::MapNodes> mapNodesOf(const SavedMap& saved, const Config& config);

}  // namespace swslam::app
