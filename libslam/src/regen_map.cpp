#include "swslam/system/regen_map.h"

#include "swslam/map/map_builder.h"
#include "swslam/system/scan_source.h"

#include <cmath>
#include <stdexcept>

namespace swslam
{
mrpt::maps::COccupancyGridMap2D regenerateMap(const PoseGraph& graph,
                                              const std::vector<StampedPose>& keyframes,
                                              const std::string& log_path, const MapParams& params,
                                              const CarmenParams& carmen, RegenReport* report)
{
  if (keyframes.size() != graph.nodeCount())
    throw std::runtime_error("regen-map: " + std::to_string(keyframes.size()) + " keyframes but " +
                             std::to_string(graph.nodeCount()) + " graph nodes (not the same run?)");
  MapBuilder builder(params);
  auto source = openScanSource(log_path, ScanSourceOptions{false, ""}, carmen);
  ScanInput in;
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

}  // namespace swslam
