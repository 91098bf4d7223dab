#pragma once
// 16 scans of the test room along a closed loop (a revisit of the start at the end), shared
// by the tests of the scans' consistency and of their optimum.

#include "test_support.h"

#include <swslam/sensor/scan.h>

#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <random>
#include <vector>

namespace swslam::test
{
struct RoomLoop
{
  std::vector<sensor::Scan> scans;
  std::vector<mrpt::poses::CPose2D> poses;
  RoomLoop()
  {
    const auto world = roomWorld();
    std::mt19937 rng(3);
    for (int k = 0; k < 16; k++)
    {
      const double a = 2 * M_PI * k / 16;
      poses.emplace_back(3 * std::cos(a) - 1, 2 * std::sin(a), a + M_PI / 2);
      scans.push_back(sensor::scanFromObservation(simulateObservation(world, poses.back(), 361, M_PI, 30, 0.005, rng)));
    }
  }
};

}  // namespace swslam::test
