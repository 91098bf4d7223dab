#include <swslam/sensor/compact_scan.h>

#include <mrpt/obs/CSinCosLookUpTableFor2DScans.h>

#include <stdexcept>

namespace swslam::sensor
{
namespace
{
// The fields a Scan and a CompactScan share: everything but the per-ray vectors.
template <class From, class To>
void copyScanHeader(const From& from, To& to)
{
  to.sensor_pose = from.sensor_pose;
  to.timestamp = from.timestamp;
  to.sensor_label = from.sensor_label;
  to.beam_count = from.beam_count;
  to.aperture = from.aperture;
  to.max_range = from.max_range;
  to.right_to_left = from.right_to_left;
  to.rejected = from.rejected;
}
}  // namespace

CompactScan compactScan(const Scan& scan)
{
  const size_t n = scan.size();
  if (scan.angles.size() != n || scan.points.size() != n || scan.beam_index.size() != n)
    throw std::invalid_argument("compactScan: the scan's per-ray vectors differ in length");
  CompactScan c;
  c.ranges.reserve(n);
  c.beam_index.reserve(n);
  for (size_t k = 0; k < n; k++)
  {
    const float r = static_cast<float>(scan.ranges[k]);
    if (static_cast<double>(r) != scan.ranges[k] || scan.beam_index[k] < 0)
      throw std::invalid_argument("compactScan: ray " + std::to_string(k) +
                                  " was not read from an observation (range not a float, or no beam)");
    c.ranges.push_back(r);
    c.beam_index.push_back(static_cast<uint32_t>(scan.beam_index[k]));
  }
  copyScanHeader(scan, c);
  return c;
}

Scan expandScan(const CompactScan& c)
{
  Scan s;
  copyScanHeader(c, s);
  const size_t n = c.ranges.size();
  s.angles.reserve(n);
  s.ranges.reserve(n);
  s.points.reserve(n);
  s.beam_index.reserve(n);
  // The table scanFromCheckedObservation used: MRPT keys it by these three properties.
  thread_local mrpt::obs::CSinCosLookUpTableFor2DScans sincos_cache;
  const auto& sc = sincos_cache.getSinCosForScan(
      mrpt::obs::T2DScanProperties{c.beam_count, c.aperture, c.right_to_left});
  for (size_t k = 0; k < n; k++)
  {
    const size_t i = c.beam_index[k];
    if (i >= c.beam_count) throw std::invalid_argument("expandScan: beam index past the scan's beams");
    const double r = c.ranges[k];
    s.angles.push_back(beamAngle(i, c.beam_count, c.aperture, c.right_to_left));
    s.ranges.push_back(r);
    s.points.emplace_back(r * sc.ccos[i], r * sc.csin[i]);
    s.beam_index.push_back(static_cast<int>(i));
  }
  return s;
}

}  // namespace swslam::sensor
