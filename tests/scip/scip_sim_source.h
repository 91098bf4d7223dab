#pragma once
// Scans for the SCIP emulator ray-cast by the project's simulator: the scenario's world,
// its vehicle on the ground-truth path, and its LiDAR (noise and dropouts included).
// Scan k is taken at t = k / rate along the path (the path's end holds the last pose),
// with one range per sensor step; rays without return are sent as kNoEcho.

#include "scip_protocol.h"

#include <swslam/sim/scenario.h>

#include <mrpt/poses/CPose2D.h>

#include <memory>

namespace swslam::scip
{
class SimScanSource
{
 public:
  /** Builds the world of `sc`. Throws std::invalid_argument if the scenario does not
   * check, or if its sensor does not sweep the steps of `sensor` (fov = (AMAX - AMIN)
   * steps, resolution = 360 deg / ARES) at its rate (SCAN / 60). */
  explicit SimScanSource(const sim::Scenario& sc, const SensorInfo& sensor = {});

  /** Scan k, ranges in mm (copies share the world; not to be called concurrently). */
  Scan operator()(uint64_t k) const;

  /** Ground-truth vehicle pose of scan k. */
  mrpt::poses::CPose2D pose(uint64_t k) const;
  /** Scans until the end of the path. */
  uint64_t pathScans() const;
  double rate() const;  ///< [Hz]

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

}  // namespace swslam::scip
