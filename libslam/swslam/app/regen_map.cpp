#include <swslam/app/regen_map.h>

#include <swslam/io/scan_source.h>
#include <swslam/map/builder.h>

#include <cmath>
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
  io::ScanSourceOptions options = scans;
  options.use_odometry = false;
  auto source = io::openScanSource(log_path, options, carmen);
  sensor::ScanInput in;
  size_t next = 0;  // keyframes are in time order: one pass over the log
  while (next < keyframes.size() && source->next(in))
  {
    const double t = mrpt::Clock::toDouble(in.observation->timestamp);
    if (std::abs(t - keyframes[next].t) > 1e-5) continue;
    if (!graph.hasNode(next)) throw std::runtime_error("regen-map: the graph has no node " + std::to_string(next));
    builder.insert(next, *in.observation, graph.pose(next));
    next++;
  }
  if (next < keyframes.size())
  {
    char buf[200];
    std::snprintf(buf, sizeof(buf), "regen-map: node %zu's scan (t = %.6f s) is not in '%s'", next,
                  keyframes[next].t, log_path.c_str());
    throw std::runtime_error(buf);
  }
  if (report) *report = RegenReport{graph.nodeCount(), next};
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
