#pragma once
// Benchmark of map construction on a log with reference poses: insertion, update of a moved
// node, re-insertion of every node after a "loop closure", snapshot copies, memory.

#include <swslam/io/scans_with_truth.h>
#include <swslam/map/builder.h>

#include <string>

namespace swslam::bench
{
struct MapBenchmarkFigures
{
  size_t nodes = 0, rays_per_scan = 0;
  double insert_avg_ms = 0, insert_max_ms = 0;     ///< one scan inserted
  double update_avg_ms = 0, update_max_ms = 0;     ///< one node moved (remove + insert)
  double reinsert_all_ms = 0;                      ///< reinsertMoved() over every node
  double snapshot_ms = 0;                          ///< one snapshot copy
  size_t grid_cells = 0, bytes = 0;
  double contribution_cells_avg = 0;               ///< touched cells per scan
};

/** Inserts every `node_every`-th scan of `data` at its reference pose, then moves each node
 * by (0.3 m, -0.2 m, 1 deg) one by one, then moves them all back with one reinsertMoved().
 * `builder` receives the nodes (its final map is the map at the reference poses). */
MapBenchmarkFigures benchmarkMapBuilder(const io::ScansWithTruth& data, size_t node_every,
                                        map::MapBuilder& builder);

std::string formatFigures(const MapBenchmarkFigures& f);

}  // namespace swslam::bench
