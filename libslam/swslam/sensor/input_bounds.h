#pragma once
// The bounds every reader applies to a scan where it enters (rawlog, CARMEN log, ROS bag; the
// system's input gate again for any source): a value past them is damage or another unit,
// not a sensor, and would make the later steps allocate or compute without bound
// (doc/reliability.md).

#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace swslam::sensor
{
/** [m] The farthest a sensor is mounted from the vehicle's origin: a few tens of metres
 * covers any vehicle (a sensor on a mast, a trailer); a pose farther out is a corrupt pose or
 * a unit mistake, and would spread one scan's points over kilometres. */
constexpr double kMaxMountingDistance = 50.0;

/** Rays of one scan, at most: far above any 2D scanner (the largest have tens of thousands of
 * rays); a larger count is damage. */
constexpr uint64_t kMaxScanRays = uint64_t(1) << 20;

/** Why `pose`, a sensor's pose on the vehicle, is no mounting ("" if it is one): an entry of
 * its matrix not finite, or its position farther than kMaxMountingDistance from the
 * vehicle's origin. */
std::string mountingProblem(const mrpt::poses::CPose3D& pose);

/** Why a scan of `rays` rays is refused ("" if it is not): more than kMaxScanRays. */
std::string rayCountProblem(uint64_t rays);

}  // namespace swslam::sensor
