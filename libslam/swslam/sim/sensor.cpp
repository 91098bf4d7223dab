#include <swslam/sim/sensor.h>

#include <swslam/sensor/scan.h>

#include <cmath>

namespace swslam::sim
{
LidarSimulator::LidarSimulator(const SensorParams& params, const ShapeGrid& grid, uint64_t seed)
    : p_(params), grid_(grid), seed_(mix64(seed)), rng_(mix64(seed ^ 0x11DA5ull))
{
  const size_t n = p_.rays();
  for (size_t i = 0; i < n; i++)
  {
    const double a = sensor::beamAngle(i, n, p_.fov);  // MRPT's convention, right to left
    cos_.push_back(std::cos(a));
    sin_.push_back(std::sin(a));
  }
}

Ray LidarSimulator::beamRay(const mrpt::poses::CPose2D& sensor, size_t beam, uint64_t index) const
{
  const double c = std::cos(sensor.phi()), s = std::sin(sensor.phi());
  Ray r;
  r.origin = {sensor.x(), sensor.y()};
  r.dir = {c * cos_[beam] - s * sin_[beam], s * cos_[beam] + c * sin_[beam]};
  r.key = mix64(seed_ ^ (index << 20) ^ beam);
  return r;
}

double LidarSimulator::trueRange(const mrpt::poses::CPose2D& vehicle, size_t beam,
                                 uint64_t index) const
{
  const mrpt::poses::CPose2D sensor = vehicle + mrpt::poses::CPose2D(p_.pose_x, p_.pose_y, p_.pose_yaw);
  return grid_.cast(beamRay(sensor, beam, index), p_.max_range);
}

mrpt::obs::CObservation2DRangeScan::Ptr LidarSimulator::scan(const mrpt::poses::CPose2D& vehicle,
                                                             mrpt::Clock::time_point stamp,
                                                             uint64_t index)
{
  const mrpt::poses::CPose2D sensor =
      vehicle + mrpt::poses::CPose2D(p_.pose_x, p_.pose_y, p_.pose_yaw);
  auto obs = mrpt::obs::CObservation2DRangeScan::Create();
  obs->sensorLabel = p_.label;
  obs->timestamp = stamp;
  obs->aperture = static_cast<float>(p_.fov);
  obs->rightToLeft = true;
  obs->maxRange = static_cast<float>(p_.max_range);
  obs->stdError = static_cast<float>(p_.range_noise_std);
  obs->sensorPose = mrpt::poses::CPose3D(p_.pose_x, p_.pose_y, p_.pose_z, p_.pose_yaw, 0, 0);
  const size_t n = rays();
  obs->resizeScan(n);

  std::normal_distribution<double> noise(0.0, p_.range_noise_std);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const float no_return = static_cast<float>(p_.max_range);
  for (size_t i = 0; i < n; i++)
  {
    const double t = grid_.cast(beamRay(sensor, i, index), p_.max_range);
    // Draw both numbers for every ray so the random stream never depends on the world.
    const double r = t + noise(rng_);
    const bool dropped = unit(rng_) < p_.dropout_prob;
    const bool valid = t != kNoHit && !dropped && t >= p_.min_range && r < p_.max_range && r > 0;
    obs->setScanRange(i, valid ? static_cast<float>(r) : no_return);
    obs->setScanRangeValidity(i, valid);
  }
  return obs;
}

}  // namespace swslam::sim
