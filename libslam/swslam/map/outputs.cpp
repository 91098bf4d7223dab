#include <swslam/map/outputs.h>

#include <swslam/map/files.h>
#include <swslam/map/map_picture.h>
#include <swslam/map/octomap_export.h>
#include <swslam/map/render.h>

#include <filesystem>
#include <functional>
#include <stdexcept>

namespace swslam::map
{
std::vector<OutputProblem> writeMapOutputs(const std::string& dir, const mrpt::maps::COccupancyGridMap2D& grid,
                                           const MapParams& params, const Overlay& overlay, bool render)
{
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);  // a missing output folder is made
  if (!std::filesystem::is_directory(dir))
    throw std::invalid_argument("map outputs: '" + dir + "' is not a directory and cannot be created" +
                                (ec ? ": " + ec.message() : std::string()));
  const std::filesystem::path d(dir);
  std::vector<OutputProblem> problems;
  auto attempt = [&](const char* file, const std::function<void(const std::string&)>& write) {
    try
    {
      write((d / file).string());
    }
    catch (const std::exception& e)
    {
      problems.push_back({file, e.what()});
    }
  };
  attempt("map.gridmap.gz", [&](const std::string& p) { writeGridmap(grid, p); });
  attempt("map.png", [&](const std::string& p) { writeMapPicture(grid, overlay, p); });
  attempt("map.yaml", [&](const std::string& p) {
    writeRosMap(grid, p, RosMapThresholds{params.occupied_thresh, params.free_thresh});
  });
  attempt("map.bt", [&](const std::string& p) { writeOctomap(grid, p, params.occupied_thresh, params.free_thresh); });
  if (render) attempt("render.png", [&](const std::string& p) { renderMap(grid, overlay, p); });
  return problems;
}

}  // namespace swslam::map
