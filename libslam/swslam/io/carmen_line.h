#pragma once
// One line of a CARMEN log, parsed into plain values. Formats (CARMEN logger, Radish logs):
//   PARAM name value [host logger_ts]
//   ODOM x y theta tv rv accel ipc_ts [host logger_ts]
//   FLASER|RLASER n r_1..r_n x y theta odom_x odom_y odom_theta ipc_ts [host logger_ts]
//   ROBOTLASER1|2 type start_angle fov resolution max_range accuracy remission_mode
//       n r_1..r_n m e_1..e_m laser_x laser_y laser_theta robot_x robot_y robot_theta
//       tv rv forward_safety side_safety turn_axis ipc_ts [host logger_ts]
//   RAWLASER1..4 type start_angle fov resolution max_range accuracy remission_mode
//       n r_1..r_n m e_1..e_m ipc_ts [host logger_ts]
// Angles in radians, ranges in metres, timestamps in seconds.

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose2D.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace swslam::io
{
/** A known message that cannot be parsed; what() names the problem (not the line number). */
class CarmenLineError : public std::runtime_error
{
 public:
  using std::runtime_error::runtime_error;
};

/** A laser message (FLASER, RLASER, ROBOTLASER*, RAWLASER*). */
struct CarmenLaser
{
  std::string label;          ///< the message name, e.g. "FLASER"
  std::vector<float> ranges;  ///< as logged, beam 0 first (rightmost for CARMEN lasers)
  /** Beam geometry carried by the line (ROBOTLASER*, RAWLASER*); FLASER/RLASER have none. */
  bool has_geometry = false;
  double start_angle = 0;  ///< angle of beam 0 [rad]
  double fov = 0;          ///< field of view [rad]
  double resolution = 0;   ///< angle between beams [rad]
  double max_range = 0;    ///< sensor maximum [m], as logged
  /** Reference robot pose of the scan (FLASER/RLASER x y theta, ROBOTLASER robot pose). */
  bool has_pose = false;
  mrpt::math::TPose2D robot_pose;
  /** Global laser pose (ROBOTLASER only): the sensor offset is robot_pose^-1 + laser_pose. */
  bool has_laser_pose = false;
  mrpt::math::TPose2D laser_pose;
  /** The robot's odometry pose when the scan was taken (FLASER/RLASER odom_x odom_y
   * odom_theta): a raw log's odometry, the reference pose again in a corrected log. */
  bool has_odometry = false;
  mrpt::math::TPose2D odometry_pose;
  double timestamp = 0;  ///< ipc_timestamp [s]
};

/** The laser's pose on the robot that a ROBOTLASER line's two global poses state:
 * robot_pose^-1 (+) laser_pose. */
mrpt::poses::CPose2D carmenLaserMounting(const CarmenLaser& laser);

struct CarmenOdometry
{
  mrpt::math::TPose2D pose;
  double tv = 0, rv = 0;  ///< translational [m/s] and rotational [rad/s] velocity
  double timestamp = 0;   ///< ipc_timestamp [s]
};

struct CarmenLine
{
  enum class Kind
  {
    Blank,    ///< empty line or '#' comment
    Unknown,  ///< a message type this parser does not convert (kept in `message`)
    Param,
    Odometry,
    Laser
  };
  Kind kind = Kind::Blank;
  std::string message;  ///< first token of the line
  std::string param_name, param_value;
  CarmenOdometry odometry;
  CarmenLaser laser;
};

/** Parses one line. Throws CarmenLineError naming the problem when a known message is
 * malformed: missing or extra fields, a non-numeric or non-finite field (ranges may be
 * nan/inf: they become invalid rays), or an implausible beam count. A timestamp out of range
 * is the log reader's to judge (carmen_log.h). */
CarmenLine parseCarmenLine(const std::string& line);

/** The sensor a laser message comes from: "front", "rear", "laser3" or "laser4"
 * (the infix of CARMEN's PARAM names, e.g. laser_front_laser_fov). */
std::string carmenSensorOf(const std::string& label);

}  // namespace swslam::io
