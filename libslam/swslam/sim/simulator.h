#pragma once
// The simulator run: checks the scenario and builds its world, then writes the rawlog
// (scans and optional odometry), the ground truth (TUM and MRPT text) and the world
// picture. Everything is checked before the first output file is created.

#include <swslam/sim/scenario.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace swslam::sim
{
struct SimulationSummary
{
  std::string name;
  size_t scans = 0, rays_per_scan = 0, shapes = 0;
  double path_length = 0;         ///< [m]
  double duration = 0;            ///< [s] of simulated time
  double generation_seconds = 0;  ///< wall-clock time spent generating and writing the rawlog
  double valid_min = 0, valid_median = 0, valid_mean = 0;  ///< fraction of valid rays per scan
  double longest_sparse_seconds = 0;  ///< longest stretch with < 10% valid rays [s]
  std::vector<std::pair<std::string, uintmax_t>> files;  ///< written files and their sizes
};

/** Runs `sc`, writing into `output_dir` (created if missing). Throws
 * std::invalid_argument (before writing anything) if the scenario does not fit. */
SimulationSummary runSimulation(const Scenario& sc, const std::string& output_dir);

/** Human-readable figures of a run. */
std::string formatSummary(const SimulationSummary& s);

}  // namespace swslam::sim
