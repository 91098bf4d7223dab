#pragma once
// The simulated 2D LiDAR: casts one ray per beam through the shape grid, adds Gaussian
// range noise and random dropouts, and reports rays with no return (nothing within
// max range, closer than min range, or dropped) as invalid with range = max range.

#include <swslam/sim/grid.h>
#include <swslam/sim/scenario.h>

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <random>
#include <vector>

namespace swslam::sim
{
class LidarSimulator
{
 public:
  LidarSimulator(const SensorParams& params, const ShapeGrid& grid, uint64_t seed);

  /** The scan number `index` taken with the vehicle at `vehicle`. Deterministic given
   * the seed and the sequence of calls. */
  mrpt::obs::CObservation2DRangeScan::Ptr scan(const mrpt::poses::CPose2D& vehicle,
                                               mrpt::Clock::time_point stamp, uint64_t index);

  /** Noise-free distance along beam `beam` from the sensor at `vehicle`, or kNoHit. */
  double trueRange(const mrpt::poses::CPose2D& vehicle, size_t beam, uint64_t index) const;

  size_t rays() const { return cos_.size(); }

 private:
  SensorParams p_;
  const ShapeGrid& grid_;
  uint64_t seed_;
  std::mt19937_64 rng_;
  std::vector<double> cos_, sin_;  ///< beam directions in the sensor frame

  Ray beamRay(const mrpt::poses::CPose2D& sensor, size_t beam, uint64_t index) const;
};

}  // namespace swslam::sim
