#pragma once
// A saved map of a test world for the localization tests: nodes along a path, their scans
// simulated, and the occupancy grid they make.

#include <swslam/localize/map_nodes.h>
#include <swslam/sensor/scan.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <memory>
#include <random>
#include <vector>

#include "test_support.h"

namespace swslam::test
{
/** 541 rays over 270 degrees, 30 m, 1 cm noise, from a sensor mounted 0.3 m ahead. */
inline mrpt::obs::CObservation2DRangeScan::Ptr localizeObservation(const World& world,
                                                                   const mrpt::poses::CPose2D& vehicle,
                                                                   std::mt19937& rng, double stamp)
{
  const mrpt::poses::CPose2D mount(0.3, 0, 0);
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>(
      simulateObservation(world, vehicle + mount, 541, 1.5 * M_PI, 30, 0.01, rng));
  obs->sensorPose = mrpt::poses::CPose3D(mount);
  obs->timestamp = mrpt::Clock::fromDouble(stamp);
  return obs;
}

struct SavedWorldMap
{
  std::vector<mrpt::poses::CPose2D> poses;
  std::vector<sensor::Scan> scans;
  mrpt::maps::COccupancyGridMap2D grid{-15, 15, -10, 10, 0.1f};
};

/** Nodes at `poses` in `world`, and their grid. */
inline SavedWorldMap savedWorldMap(const World& world, const std::vector<mrpt::poses::CPose2D>& poses,
                                   unsigned seed = 1)
{
  std::mt19937 rng(seed);
  SavedWorldMap m;
  m.poses = poses;
  for (size_t k = 0; k < poses.size(); ++k)
  {
    const auto obs = localizeObservation(world, poses[k], rng, 1000.0 + k);
    m.scans.push_back(sensor::scanFromObservation(*obs));
    m.grid.insertObservation(*obs, mrpt::poses::CPose3D(poses[k]));
  }
  return m;
}

}  // namespace swslam::test
