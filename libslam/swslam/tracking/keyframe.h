#pragma once
// A graph node made by tracking: its pose, and the forms of its scan that later scans match
// against. Tracking matches only its last keyframes again (LocalTracker::kept()); an older
// keyframe holds no scan (the graph module keeps every node's scan, compact).

#include <swslam/plicp/plicp.h>
#include <swslam/tracking/ambiguity.h>

#include <mrpt/poses/CPose2D.h>
#include <mrpt/system/datetime.h>

#include <cstddef>
#include <memory>

namespace swslam::tracking
{
struct Keyframe
{
  size_t id = 0;
  mrpt::poses::CPose2D pose;  ///< vehicle pose in the map frame (updated by the optimizer)
  std::shared_ptr<const plicp::ReferenceScan> scan;  ///< null once the keyframe is not kept
  std::shared_ptr<const FacingNormals> facing;  ///< of scan's points (tracking/ambiguity.h); the same
  mrpt::poses::CPose2D sensor_pose;  ///< sensor mounting on the vehicle
  mrpt::Clock::time_point timestamp;
};

}  // namespace swslam::tracking
