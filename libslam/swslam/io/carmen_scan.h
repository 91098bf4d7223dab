#pragma once
// One CARMEN laser line as an MRPT scan: its sensor pose, aperture and maximum range by the
// rules of doc/carmen.md, and its rays.

#include <swslam/io/carmen_line.h>
#include <swslam/io/carmen_params.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>

namespace swslam::io
{
/** How one laser line becomes a scan. */
struct CarmenScanGeometry
{
  mrpt::poses::CPose2D sensor_pose;  ///< on the robot, including a start-angle offset
  double aperture = M_PI;            ///< MRPT aperture: first to last beam [rad]
  double max_range = 0;              ///< readings >= this are invalid ("no return") [m]
  std::string max_range_source;      ///< which rule gave max_range
  std::string warning;               ///< non-empty: an inconsistency worth reporting
};

/** Numeric PARAM values read so far, by name. */
using CarmenLogParams = std::map<std::string, double>;

/** Geometry of a laser line: sensor pose, aperture and max range, by the rules of
 * doc/carmen.md. `saturation` is the detected saturation value of this laser (if any)
 * and `largest` its largest reading in the whole log. */
CarmenScanGeometry carmenScanGeometry(const CarmenLaser& laser, const CarmenLogParams& log_params,
                                      const CarmenParams& params,
                                      std::optional<double> saturation, double largest);

/** Sensor pose on the robot from PARAM offsets (CARMEN convention: the front laser looks
 * forward `offset` metres ahead of the centre, the rear laser backwards, `offset` behind);
 * identity for another sensor. */
mrpt::poses::CPose2D carmenOffsetPose(const std::string& sensor, const CarmenLogParams& log_params);

/** True for the PARAM names that carmenScanGeometry() reads (offsets, FOV, resolution,
 * max range of the front and rear lasers); their values must be numbers. */
bool carmenParamIsUsed(const std::string& name);

/** The MRPT scan of a laser line: rays invalid when non-finite, <= 0 or >= max_range. */
mrpt::obs::CObservation2DRangeScan::Ptr carmenScan(const CarmenLaser& laser,
                                                   const CarmenScanGeometry& geometry,
                                                   double timestamp);

}  // namespace swslam::io
