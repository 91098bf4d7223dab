#pragma once
// ROS 1 messages <-> MRPT observations, for bags (bag_reader, rawlog2bag). Times and poses go
// through MRPT's ROS 1 bridge; the scan's rays do not: the bridge maps each MRPT ray to a ROS
// index by truncating a float product, which moves rays by one index and drops the last one
// (a 5-ray scan r0..r4 comes back as r0 r0 r1 r2 r3), and it keeps no ray past 99% of
// range_max. Here every ray keeps its index and angle.

#include <swslam/io/bag_reader.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose3D.h>

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <cstdint>
#include <string>
#include <vector>

namespace swslam::io
{
/** A LaserScan's angles agree when its last ray, at angle_min + (rays - 1) angle_increment,
 * is at angle_max within this fraction of an increment (or one increment before it: some
 * drivers state the end of a full turn). */
constexpr double kAngleTolerance = 0.5;

/** Why a LaserScan's angles are not those of `rays` rays ("" if they are): an angle not finite,
 * a zero increment, or angle_min + (rays - 1) angle_increment not at angle_max (within
 * kAngleTolerance increments, or one increment before it). A negative increment from a larger
 * angle_min down to angle_max is a scan published right to left, and agrees. */
std::string laserScanAnglesProblem(double angle_min, double angle_max, double angle_increment, size_t rays);

/** The scan of `msg`, labelled `label`, from a sensor at `sensor_pose` on the vehicle. Ray i
 * of a ROS scan points at angle_min + i * angle_increment: the MRPT scan (symmetric about its
 * own x axis) gets the same rays in counter-clockwise order (a scan published right to left,
 * with a negative increment, reversed), its x axis turned to the middle of the fan (folded
 * into sensorPose). A ray is valid if finite and within [range_min, range_max] (REP 117: NaN
 * and +-inf are no measurement); an invalid ray that is not finite reads range_max. Throws
 * std::invalid_argument naming the problem if the scan has fewer than 2 rays or more than
 * sensor::kMaxScanRays, or its angles disagree (laserScanAnglesProblem). */
mrpt::obs::CObservation2DRangeScan scanFromRos(const sensor_msgs::LaserScan& msg, const std::string& label,
                                               const mrpt::poses::CPose3D& sensor_pose);

/** The scan as a ROS message in frame `frame_id` (its pose on the vehicle goes to
 * /tf_static): rays counter-clockwise from -aperture/2; invalid rays +inf (no return). */
sensor_msgs::LaserScan scanToRos(const mrpt::obs::CObservation2DRangeScan& scan, const std::string& frame_id);

/** The planar odometry of `msg` (its pose's x, y and yaw; the twist as local velocities).
 * Throws std::invalid_argument naming it if its orientation is no rotation (a quaternion not
 * finite or not of norm 1: MRPT's own check would throw a logic_error with a call stack). */
mrpt::obs::CObservationOdometry odometryFromRos(const nav_msgs::Odometry& msg, const std::string& label);

/** The odometry as a ROS message: pose of `child_frame` in `frame`. */
nav_msgs::Odometry odometryToRos(const mrpt::obs::CObservationOdometry& odo, const std::string& frame,
                                 const std::string& child_frame);

/** A static transform: the pose of `child` in `parent`, stamped `stamp`. */
geometry_msgs::TransformStamped transformToRos(const mrpt::poses::CPose3D& pose, const std::string& parent,
                                               const std::string& child, const ros::Time& stamp);

/** The pose of `child` in `parent` that a transform message states. Throws
 * std::invalid_argument if its rotation is no rotation (as odometryFromRos). */
mrpt::poses::CPose3D transformFromRos(const geometry_msgs::Transform& t);

/** The pose of frame `child` in frame `ancestor`, composed along the parent links of
 * `transforms` (a tf tree); false if `ancestor` is not above `child` in it. */
bool poseInAncestor(const std::vector<geometry_msgs::TransformStamped>& transforms, const std::string& child,
                    const std::string& ancestor, mrpt::poses::CPose3D& pose);

/** The scanner's pose for a bag (ROS 1 or 2) at `path`: the pose of the scans' frame
 * `scan_frame` in the vehicle's frame (the odometry's child frame `odom_child`, else
 * base_link) composed from the /tf_static `transforms`; identity, its source saying why, if
 * the scans are in the vehicle's frame, if `tf_problem` (a /tf_static message that could not
 * be read) is not empty, or if no transforms link the frames. Throws std::runtime_error
 * "bag 'P': /tf_static 'base' -> 'scan': ..." if the pose is no mounting
 * (sensor::mountingProblem) or a transform's rotation is no rotation. */
SensorMounting mountingFromTf(const std::string& scan_frame, const std::string& odom_child,
                              const std::vector<geometry_msgs::TransformStamped>& transforms,
                              const std::string& tf_problem, const std::string& path);

/** Why the serialized `bytes` are not a well-formed message of that type ("" if they are): the
 * lengths its arrays state must fit in the bytes, checked before ROS's deserializer sizes a
 * vector by them (it allocates first: a corrupt length would ask for gigabytes); a scan has at
 * most sensor::kMaxScanRays rays, as in every format. */
std::string laserScanLayoutProblem(const std::vector<uint8_t>& bytes);
std::string tfMessageLayoutProblem(const std::vector<uint8_t>& bytes);

}  // namespace swslam::io
