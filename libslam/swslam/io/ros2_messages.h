#pragma once
// The three ROS 2 messages swslam reads, decoded from CDR (and written as CDR, for
// swslam-rawlog2bag's ROS 2 bags) (cdr_reader.h) into the ROS 1
// message structs, the values ros_conversion.h turns into observations for both bag formats:
// a ROS 2 bag's scan is converted by the very code that converts a ROS 1 bag's. The ROS 2
// layouts differ from ROS 1's in the header (no seq; the stamp an int32 sec and a uint32
// nanosec) and in the CDR alignment of the float64 fields.

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace swslam::io
{
/** sensor_msgs/msg/LaserScan. Throws CdrError naming the byte if the bytes are not one (a
 * length past the end, a stamp before 1970 or nanoseconds past a second), and naming the
 * count if it has more rays (or intensities) than sensor::kMaxScanRays, before it allocates. */
sensor_msgs::LaserScan laserScanFromCdr(const uint8_t* data, size_t size);

/** nav_msgs/msg/Odometry (the covariances are read and dropped). Throws CdrError. */
nav_msgs::Odometry odometryFromCdr(const uint8_t* data, size_t size);

/** tf2_msgs/msg/TFMessage. Throws CdrError. */
tf2_msgs::TFMessage tfMessageFromCdr(const uint8_t* data, size_t size);

/** The same three messages written as CDR (cdr_writer.h), in either byte order: what the
 * decoders above read back to the same values. */
std::vector<uint8_t> laserScanCdr(const sensor_msgs::LaserScan& m, bool big_endian = false);
std::vector<uint8_t> odometryCdr(const nav_msgs::Odometry& m, bool big_endian = false);
std::vector<uint8_t> tfMessageCdr(const tf2_msgs::TFMessage& m, bool big_endian = false);

}  // namespace swslam::io
