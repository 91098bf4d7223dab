#pragma once
// What a scan source hands the SLAM system: one laser scan and the odometry since the last.

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

namespace swslam::sensor
{
/** One input scan, with the vehicle's odometry increment since the previous scan if known. */
struct ScanInput
{
  mrpt::obs::CObservation2DRangeScan::Ptr observation;
  std::optional<mrpt::poses::CPose2D> odometry_increment;
};

}  // namespace swslam::sensor
