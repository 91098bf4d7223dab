#include <swslam/geometry/pose_threshold.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace swslam::geometry
{
bool movedBeyond(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b,
                 const MoveThreshold& threshold)
{
  return a.distanceTo(b) > threshold.translation ||
         std::abs(mrpt::math::wrapToPi(b.phi() - a.phi())) > threshold.rotation;
}

}  // namespace swslam::geometry
