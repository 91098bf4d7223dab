#pragma once
// Output files of the simulator besides the rawlog: the ground truth in MRPT's text
// format and a top view of the world with the ground-truth path. Written atomically.

#include <swslam/common/tum_io.h>
#include <swslam/sim/world.h>

#include <mrpt/img/CImage.h>

#include <string>
#include <vector>

namespace swslam::sim
{
/** Ground truth as MRPT's GridMapNavSimul writes it and graphslam-engine reads it
 * (format "NavSimul"): one line "timestamp x y phi" per pose, no header. */
std::string formatMrptGroundTruth(const std::vector<common::StampedPose>& poses);
void writeMrptGroundTruth(const std::string& path, const std::vector<common::StampedPose>& poses);

/** Top view: water blue, land beige, shore brown, rocks grey, trunks dark green, bushes
 * light green, reeds olive; the path in red from a white start dot. About `max_side`
 * pixels along the longer side. */
mrpt::img::CImage drawWorld(const World& world, const std::vector<Eigen::Vector2d>& path,
                            int max_side = 800);
void writeWorldPicture(const std::string& png_path, const World& world,
                       const std::vector<Eigen::Vector2d>& path);

}  // namespace swslam::sim
