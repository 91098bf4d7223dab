#include <swslam/plicp/decimation.h>

#include <cmath>
#include <stdexcept>

namespace swslam::plicp
{
size_t decimationStride(const sensor::Scan& s, double spacing)
{
  if (!(spacing > 0) || s.beam_count < 2 || !(s.aperture > 0)) return 1;
  const double beam = s.aperture / static_cast<double>(s.beam_count - 1);
  const double k = std::round(spacing / beam);
  return k > 1 ? static_cast<size_t>(k) : 1;
}

sensor::Scan decimated(const sensor::Scan& s, size_t k)
{
  if (k <= 1) return s;
  sensor::Scan out;
  out.sensor_pose = s.sensor_pose;
  out.timestamp = s.timestamp;
  out.sensor_label = s.sensor_label;
  out.beam_count = s.beam_count;
  out.aperture = s.aperture;
  out.max_range = s.max_range;
  out.rejected = s.rejected;
  if (s.angles.size() != s.size() || s.points.size() != s.size() || s.beam_index.size() != s.size())
    throw std::invalid_argument("decimated: the scan's angles, ranges, points and beam indices differ in length");
  const size_t n = (s.size() + k - 1) / k;
  out.angles.reserve(n);
  out.ranges.reserve(n);
  out.points.reserve(n);
  out.beam_index.reserve(n);
  for (size_t i = 0; i < s.size(); i += k)
  {
    out.angles.push_back(s.angles[i]);
    out.ranges.push_back(s.ranges[i]);
    out.points.push_back(s.points[i]);
    out.beam_index.push_back(s.beam_index[i]);
  }
  return out;
}

}  // namespace swslam::plicp
