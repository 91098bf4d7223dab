#pragma once
// PLICP estimates the motion of the sensor; the graph holds vehicle poses. With the sensor
// mounted at `s` on the vehicle, a sensor motion q is the vehicle motion s (+) q (+) s^-1.

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

namespace swslam::geometry
{
/** [m] A motion estimate agrees with a reference motion when their translations differ by
 * less than this: the matcher benchmark's "under 5 cm" and the RPE's share within it
 * (doc/plicp.md, doc/evaluation.md). */
constexpr double kMotionAgreement = 0.05;

/** Vehicle motion s (+) q (+) s^-1 from sensor motion q. */
mrpt::poses::CPose2D vehicleMotion(const mrpt::poses::CPose2D& sensor_on_vehicle,
                                   const mrpt::poses::CPose2D& sensor_motion);

/** Sensor motion s^-1 (+) m (+) s from vehicle motion m (the inverse map). */
mrpt::poses::CPose2D sensorMotion(const mrpt::poses::CPose2D& sensor_on_vehicle,
                                  const mrpt::poses::CPose2D& vehicle_motion);

/** Covariance of vehicleMotion(s, q) given the covariance of q ([x, y, phi]), first order:
 * J cov J' with J = d vehicleMotion / d q, which is the rotation of the mounting for the
 * translation plus a lever-arm term for the angle. */
Eigen::Matrix3d vehicleMotionCovariance(const mrpt::poses::CPose2D& sensor_on_vehicle,
                                        const mrpt::poses::CPose2D& sensor_motion,
                                        const Eigen::Matrix3d& sensor_covariance);

}  // namespace swslam::geometry
