#include <swslam/app/regen_map.h>

#include <swslam/app/session.h>
#include <swslam/io/scan_source.h>
#include <swslam/map/builder.h>

#include <filesystem>
#include <stdexcept>

namespace swslam::app
{
mrpt::maps::COccupancyGridMap2D regenerateMap(const graph::PoseGraph& graph,
                                              const std::vector<common::StampedPose>& keyframes,
                                              const std::string& log_path, const map::MapParams& params,
                                              const io::CarmenParams& carmen, const io::ScanSourceOptions& scans,
                                              RegenReport* report)
{
  if (keyframes.size() != graph.nodeCount())
    throw std::runtime_error("regen-map: " + std::to_string(keyframes.size()) + " keyframes but " +
                             std::to_string(graph.nodeCount()) + " graph nodes (not the same run?)");
  map::MapBuilder builder(params);
  std::vector<double> times;
  for (const auto& k : keyframes) times.push_back(k.t);
  visitNodeScans(times, 0, log_path, scans, carmen, "regen-map",
                 [&](size_t id, const mrpt::obs::CObservation2DRangeScan::Ptr& obs) {
                   if (!graph.hasNode(id)) throw std::runtime_error("regen-map: the graph has no node " + std::to_string(id));
                   if (!graph.isMerged(id)) builder.insert(id, *obs, graph.pose(id));
                 });
  // Every node's scan was found (visitNodeScans throws otherwise); a merged one is not mapped.
  if (report) *report = RegenReport{graph.nodeCount(), graph.liveNodeCount()};
  return builder.snapshot();
}

std::vector<system::ScanStats> statsForPictures(const std::string& stats_path, size_t trajectory_poses,
                                                std::string& problem)
{
  problem.clear();
  if (!std::filesystem::is_regular_file(stats_path)) return {};
  std::vector<system::ScanStats> rows;
  try
  {
    rows = system::readStatsCsv(stats_path);
  }
  catch (const std::runtime_error& e)
  {
    problem = e.what();
    return {};
  }
  if (rows.size() != trajectory_poses)
  {
    problem = "stats.csv: '" + stats_path + "' has " + std::to_string(rows.size()) + " rows for a trajectory of " +
              std::to_string(trajectory_poses) + " poses (not the same run?)";
    return {};
  }
  return rows;
}

}  // namespace swslam::app
