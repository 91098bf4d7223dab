#include <swslam/app/saved_map.h>

#include <swslam/app/session.h>
#include <swslam/common/tum_io.h>
#include <swslam/graph/io.h>
#include <swslam/map/files.h>
#include <swslam/sensor/scan.h>

#include <filesystem>
#include <stdexcept>

namespace swslam::app
{
namespace fs = std::filesystem;

namespace
{
mrpt::maps::COccupancyGridMap2D readGrid(const std::string& dir)
{
  const std::string path = (fs::path(dir) / "map.gridmap.gz").string();
  if (!fs::is_regular_file(path)) throw std::invalid_argument("map '" + dir + "': map.gridmap.gz is missing");
  try
  {
    return map::readGridmap(path);
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("map '" + dir + "': map.gridmap.gz: " + e.what());
  }
}

SavedMap readRunFolder(const std::string& dir)
{
  const fs::path d(dir);
  for (const char* name : {kRunRecordFile, "graph.graph", "keyframes.tum", "map.gridmap.gz"})
    if (!fs::is_regular_file(d / name))
      throw std::invalid_argument("map '" + dir + "': " + name +
                                  " is missing (not a swslam run folder or a saved session?)");
  SavedMap m;
  m.record = readRunRecord((d / kRunRecordFile).string());
  graph::PoseGraph graph;
  std::vector<common::StampedPose> keyframes;
  try
  {
    graph::GraphLoadReport load;
    graph = graph::loadGraph((d / "graph.graph").string(), &load);
    if (load.skipped_lines > 0)
      throw std::invalid_argument("graph.graph line " + std::to_string(load.skipped_line_numbers.front()) + ": " +
                                  load.skip_reasons.front());
    keyframes = common::readTum((d / "keyframes.tum").string());
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("map '" + dir + "': " + e.what());
  }
  if (keyframes.size() != graph.nodeCount())
    throw std::invalid_argument("map '" + dir + "': keyframes.tum holds " + std::to_string(keyframes.size()) +
                                " poses, graph.graph " + std::to_string(graph.nodeCount()) + " nodes");
  std::vector<double> times;
  for (size_t id = 0; id < keyframes.size(); ++id)
  {
    if (!graph.hasNode(id))
      throw std::invalid_argument("map '" + dir + "': graph.graph has no node " + std::to_string(id) +
                                  " (its nodes are not keyframes.tum's 0.." + std::to_string(keyframes.size() - 1) + ")");
    times.push_back(keyframes[id].t);
    m.poses.push_back(graph.pose(id));
  }
  try
  {
    m.observations = nodeObservationsFromLog(times, 0, m.record.input, m.record);
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("map '" + dir + "': the nodes' scans from its input '" + m.record.input +
                                "': " + e.what());
  }
  m.grid = readGrid(dir);
  return m;
}
}  // namespace

SavedMap readSavedMap(const std::string& dir)
{
  if (!fs::is_directory(dir)) throw std::invalid_argument("map '" + dir + "': no such folder");
  if (!fs::exists(fs::path(dir) / "session.ini")) return readRunFolder(dir);
  Session s = readSession(dir);
  SavedMap m;
  m.session = true;
  m.record = std::move(s.record);
  for (size_t id = 0; id < s.resumed.graph.nodeCount(); ++id) m.poses.push_back(s.resumed.graph.pose(id));
  m.observations = std::move(s.resumed.observations);
  m.grid = readGrid(dir);
  return m;
}

std::unique_ptr<localize::MapNodes> mapNodesOf(const SavedMap& saved, const Config& cfg)
{
  std::vector<sensor::Scan> scans;
  scans.reserve(saved.observations.size());
  for (size_t id = 0; id < saved.observations.size(); ++id)
  {
    try
    {
      scans.push_back(sensor::scanFromObservation(*saved.observations[id], cfg.system.tracking.min_range));
    }
    catch (const std::exception& e)
    {
      throw std::invalid_argument("map node " + std::to_string(id) + "'s scan: " + e.what());
    }
  }
  return std::make_unique<localize::MapNodes>(saved.poses, std::move(scans), cfg.system.plicp);
}

}  // namespace swslam::app
