#include <swslam/sensor/compact_scan.h>

#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <limits>

using swslam::sensor::compactScan;
using swslam::sensor::expandScan;
using swslam::sensor::Scan;
using swslam::sensor::scanFromObservation;

namespace
{
/** A scan of `n` rays over `aperture` with random ranges, some invalid in each way. */
mrpt::obs::CObservation2DRangeScan randomObservation(size_t n, double aperture, bool right_to_left,
                                                     mrpt::random::CRandomGenerator& rng)
{
  mrpt::obs::CObservation2DRangeScan o;
  o.aperture = static_cast<float>(aperture);
  o.maxRange = 30.0f;
  o.rightToLeft = right_to_left;
  o.sensorLabel = "LIDAR";
  o.sensorPose = mrpt::poses::CPose3D(0.3, -0.1, 0, 0.2, 0, 0);
  o.timestamp = mrpt::Clock::fromDouble(1700000000.25);
  o.resizeScan(n);
  for (size_t i = 0; i < n; i++)
  {
    o.setScanRange(i, static_cast<float>(rng.drawUniform(0.0, 35.0)));
    o.setScanRangeValidity(i, rng.drawUniform(0.0, 1.0) > 0.1);
  }
  o.setScanRange(n - 1, std::numeric_limits<float>::quiet_NaN());
  o.setScanRange(0, 5.0f);
  o.setScanRangeValidity(0, true);
  return o;
}

void expectSame(const Scan& a, const Scan& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); k++)
  {
    // Bit for bit: the matcher sees the same numbers either way.
    EXPECT_EQ(a.angles[k], b.angles[k]);
    EXPECT_EQ(a.ranges[k], b.ranges[k]);
    EXPECT_EQ(a.points[k].x(), b.points[k].x());
    EXPECT_EQ(a.points[k].y(), b.points[k].y());
    EXPECT_EQ(a.beam_index[k], b.beam_index[k]);
  }
  EXPECT_EQ(a.sensor_pose, b.sensor_pose);
  EXPECT_EQ(a.timestamp, b.timestamp);
  EXPECT_EQ(a.sensor_label, b.sensor_label);
  EXPECT_EQ(a.beam_count, b.beam_count);
  EXPECT_EQ(a.aperture, b.aperture);
  EXPECT_EQ(a.max_range, b.max_range);
  EXPECT_EQ(a.right_to_left, b.right_to_left);
  EXPECT_EQ(a.rejected.total(), b.rejected.total());
  EXPECT_EQ(a.rejected.not_finite, b.rejected.not_finite);
  EXPECT_EQ(a.rejected.at_or_above_max, b.rejected.at_or_above_max);
}
}  // namespace

TEST(CompactScan, ExpandsToTheScanOfTheObservationBitForBit)
{
  mrpt::random::CRandomGenerator rng(5);
  for (const bool right_to_left : {true, false})
    for (const auto& [n, aperture] : {std::pair<size_t, double>{1081, 1.5 * M_PI}, {361, M_PI}, {720, 2 * M_PI}, {2, 0.1}})
    {
      SCOPED_TRACE(std::to_string(n) + " rays, right to left " + std::to_string(right_to_left));
      const Scan s = scanFromObservation(randomObservation(n, aperture, right_to_left, rng), 0.1);
      ASSERT_GT(s.size(), 0u);
      const auto c = compactScan(s);
      expectSame(expandScan(c), s);
      // 8 bytes a valid ray, against 36 in the Scan.
      EXPECT_LT(c.bytes(), 8 * s.size() + 400);
    }
}

TEST(CompactScan, RefusesAScanNotReadFromAnObservation)
{
  Scan s;
  s.angles = {0.0};
  s.ranges = {0.1};  // not a float's value
  s.points = {{0.1, 0.0}};
  s.beam_index = {0};
  s.beam_count = 2;
  EXPECT_THROW(compactScan(s), std::invalid_argument);
  s.ranges = {0.5};
  s.angles.push_back(1.0);
  EXPECT_THROW(compactScan(s), std::invalid_argument);
}
