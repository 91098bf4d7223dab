#include <swslam/sensor/scan.h>

#include <swslam/sensor/input_bounds.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CSinCosLookUpTableFor2DScans.h>

#include <cmath>
#include <stdexcept>

namespace swslam::sensor
{
double beamAngle(size_t i, size_t n, double aperture, bool right_to_left)
{
  const double a = -0.5 * aperture + aperture * static_cast<double>(i) / static_cast<double>(n - 1);
  return right_to_left ? a : -a;
}

void checkObservationGeometry(const mrpt::obs::CObservation2DRangeScan& obs)
{
  const size_t n = obs.getScanSize();
  const std::string who = "scan '" + obs.sensorLabel + "': ";
  if (n < 2) throw std::invalid_argument(who + "has " + std::to_string(n) + " beams (need >= 2)");
  if (!(obs.aperture > 0) || obs.aperture > 2 * M_PI + 1e-6)
    throw std::invalid_argument(who + "aperture " + std::to_string(obs.aperture) +
                                " rad is outside (0, 2*pi]");
  if (!(obs.maxRange > 0) || !std::isfinite(obs.maxRange))
    throw std::invalid_argument(who + "max range " + std::to_string(obs.maxRange) +
                                " is not a positive finite number");
  if (const std::string problem = rayCountProblem(n); !problem.empty()) throw std::invalid_argument(who + problem);
  if (const std::string problem = mountingProblem(obs.sensorPose); !problem.empty())
    throw std::invalid_argument(who + problem);
}

Scan scanFromObservation(const mrpt::obs::CObservation2DRangeScan& obs, double min_range)
{
  checkObservationGeometry(obs);
  return scanFromCheckedObservation(obs, min_range);
}

Scan scanFromCheckedObservation(const mrpt::obs::CObservation2DRangeScan& obs, double min_range)
{
  const size_t n = obs.getScanSize();
  Scan s;
  s.sensor_pose = mrpt::poses::CPose2D(obs.sensorPose);
  s.timestamp = obs.timestamp;
  s.sensor_label = obs.sensorLabel;
  s.beam_count = n;
  s.aperture = obs.aperture;
  s.max_range = obs.maxRange;
  s.right_to_left = obs.rightToLeft;
  s.angles.reserve(n);
  s.ranges.reserve(n);
  s.points.reserve(n);
  s.beam_index.reserve(n);

  // MRPT's cached per-geometry table (float, like the ranges themselves); one per thread.
  thread_local mrpt::obs::CSinCosLookUpTableFor2DScans sincos_cache;
  const auto& sc = sincos_cache.getSinCosForScan(obs);
  for (size_t k = 0; k < n; k++)
  {
    // Visit rays in increasing angle whatever the scan direction.
    const size_t i = obs.rightToLeft ? k : n - 1 - k;
    const double r = obs.getScanRange(i);
    auto& rej = s.rejected;
    if (!obs.getScanRangeValidity(i)) { rej.flagged_invalid++; continue; }
    if (!std::isfinite(r)) { rej.not_finite++; continue; }
    if (r <= 0) { rej.non_positive++; continue; }
    if (r < min_range) { rej.below_min++; continue; }
    if (r >= obs.maxRange) { rej.at_or_above_max++; continue; }
    const double a = beamAngle(i, n, obs.aperture, obs.rightToLeft);
    s.angles.push_back(a);
    s.ranges.push_back(r);
    s.points.emplace_back(r * sc.ccos[i], r * sc.csin[i]);
    s.beam_index.push_back(static_cast<int>(i));
  }
  return s;
}

double rotationLength(const std::vector<Eigen::Vector2d>& points)
{
  double sum = 0;
  for (const auto& p : points) sum += p.squaredNorm();
  if (points.empty() || !(sum > 0) || !std::isfinite(sum)) return 1.0;
  return std::sqrt(sum / static_cast<double>(points.size()));
}

}  // namespace swslam::sensor
