#include <swslam/bench/map_builder.h>

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>

namespace swslam::bench
{
namespace
{
template <class F>
double timeMs(F f)
{
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

MapBenchmarkFigures benchmarkMapBuilder(const io::ScansWithTruth& data, size_t node_every,
                                        map::MapBuilder& builder)
{
  if (node_every < 1) throw std::invalid_argument("map benchmark: node_every must be >= 1");
  if (data.scans.empty()) throw std::invalid_argument("map benchmark: no scans");
  MapBenchmarkFigures f;
  f.rays_per_scan = data.scans.front()->getScanSize();
  std::map<map::MapNodeId, mrpt::poses::CPose2D> truth;
  for (size_t k = 0; k < data.scans.size(); k += node_every)
  {
    const map::MapNodeId id = k;
    const double ms = timeMs([&] { builder.insert(id, *data.scans[k], data.truth[k]); });
    f.insert_avg_ms += ms;
    f.insert_max_ms = std::max(f.insert_max_ms, ms);
    f.contribution_cells_avg += map::computeContribution(map::sanitizedScan(*data.scans[k], builder.params()),
                                                    data.truth[k], builder.params()).cells();
    truth[id] = data.truth[k];
  }
  f.nodes = truth.size();
  f.insert_avg_ms /= f.nodes;
  f.contribution_cells_avg /= f.nodes;

  const mrpt::poses::CPose2D shift(0.3, -0.2, mrpt::DEG2RAD(1.0));
  for (const auto& [id, pose] : truth)
  {
    const double ms = timeMs([&, id = id, pose = pose] { builder.update(id, pose + shift); });
    f.update_avg_ms += ms;
    f.update_max_ms = std::max(f.update_max_ms, ms);
  }
  f.update_avg_ms /= f.nodes;
  f.reinsert_all_ms = timeMs([&] { builder.reinsertMoved(truth, builder.params().reinsertThreshold()); });
  f.snapshot_ms = timeMs([&] {
    const auto g = builder.snapshot();
    f.grid_cells = size_t(g.getSizeX()) * g.getSizeY();
  });
  f.bytes = builder.bytes();
  return f;
}

std::string formatFigures(const MapBenchmarkFigures& f)
{
  std::ostringstream o;
  o.precision(3);
  o << "nodes                     " << f.nodes << " (scans of " << f.rays_per_scan << " rays)\n"
    << "insert one scan [ms]      avg " << f.insert_avg_ms << "  max " << f.insert_max_ms << "\n"
    << "touched cells per scan    " << f.contribution_cells_avg << "\n"
    << "update one node [ms]      avg " << f.update_avg_ms << "  max " << f.update_max_ms << "\n"
    << "reinsertMoved, all [ms]   " << f.reinsert_all_ms << "\n"
    << "snapshot copy [ms]        " << f.snapshot_ms << " (" << f.grid_cells << " cells)\n"
    << "memory [MiB]              " << f.bytes / 1048576.0 << "\n";
  return o.str();
}

}  // namespace swslam::bench
