#include <swslam/sensor/input_bounds.h>

#include <mrpt/math/CMatrixFixed.h>

#include <cmath>
#include <cstdio>

namespace swslam::sensor
{
std::string mountingProblem(const mrpt::poses::CPose3D& pose)
{
  // Every entry of the 4x4 matrix: a NaN in the rotation would make every point NaN.
  const auto m = pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 4; c++)
      if (!std::isfinite(m(r, c))) return "sensor pose " + pose.asString() + " is not finite";
  const double distance = pose.translation().norm();
  if (distance <= kMaxMountingDistance) return "";
  char buf[200];
  std::snprintf(buf, sizeof(buf),
                "sensor mounted at (%g, %g, %g) m, %g m from the vehicle: beyond the %g m a sensor is mounted "
                "(a corrupt pose, or not in metres?)",
                pose.x(), pose.y(), pose.z(), distance, kMaxMountingDistance);
  return buf;
}

std::string rayCountProblem(uint64_t rays)
{
  if (rays <= kMaxScanRays) return "";
  return "a scan of " + std::to_string(rays) + " rays (more than " + std::to_string(kMaxScanRays) +
         ": a corrupt count)";
}

}  // namespace swslam::sensor
