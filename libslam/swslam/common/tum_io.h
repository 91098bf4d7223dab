#pragma once
// Trajectories in the TUM text format: "t x y z qx qy qz qw" per line, '#' comments.
// swslam is planar: z = 0 and the quaternion is a rotation about z on writing; on
// reading, the yaw of any quaternion is kept.

#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace swslam::common
{
struct StampedPose
{
  double t = 0;  ///< seconds
  mrpt::poses::CPose2D pose;
};

/** Largest position coordinate a TUM file may hold [m] (a million km: beyond any trajectory). */
constexpr double kMaxTumCoordinate = 1e9;

/** Reads a TUM file. Throws std::runtime_error naming the file and line on a malformed line,
 * a position coordinate beyond kMaxTumCoordinate, or a quaternion whose norm is not 1 (within
 * 1%). */
std::vector<StampedPose> readTum(const std::string& path);

/** Formats poses as TUM text (full precision). */
std::string formatTum(const std::vector<StampedPose>& poses);

/** Writes a TUM file atomically. */
void writeTum(const std::string& path, const std::vector<StampedPose>& poses);

}  // namespace swslam::common
