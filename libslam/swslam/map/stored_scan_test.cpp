// StoredScan: a node's scan kept in 4 bytes and a bit a ray gives back the scan the grid
// insertion reads, bit for bit, and the same contribution to the map.
#include <swslam/map/scan_contribution.h>
#include <swslam/map/stored_scan.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "map_test_support.h"

using namespace swslam;
using namespace swslam::map;
using mrpt::poses::CPose2D;

TEST(StoredScan, GivesBackTheSameRaysAndTheSameContribution)
{
  const auto p = test::smallMapParams(10);
  std::vector<double> ranges(361);
  for (size_t i = 0; i < ranges.size(); i++) ranges[i] = 3.0 + 2.0 * std::sin(0.05 * static_cast<double>(i));
  for (size_t i = 0; i < ranges.size(); i += 9) ranges[i] = -1;  // no return
  auto obs = test::makeScan(ranges, 1.5 * M_PI, 30);
  obs.setScanRange(5, std::numeric_limits<float>::quiet_NaN());  // flagged valid, NaN
  obs.setScanHasIntensity(true);
  for (size_t i = 0; i < obs.getScanSize(); i++) obs.setScanIntensity(i, static_cast<int>(i));
  obs.sensorLabel = "front";
  const auto sanitized = sanitizedScan(obs, p);

  const StoredScan stored(sanitized);
  const auto back = stored.restore();
  ASSERT_EQ(back.getScanSize(), sanitized.getScanSize());
  size_t valid = 0;
  for (size_t i = 0; i < back.getScanSize(); i++)
  {
    const float a = back.getScanRange(i), b = sanitized.getScanRange(i);
    EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i;
    EXPECT_EQ(back.getScanRangeValidity(i), sanitized.getScanRangeValidity(i)) << i;
    valid += back.getScanRangeValidity(i);
  }
  EXPECT_GT(valid, 300u);
  EXPECT_LT(valid, 361u);
  EXPECT_EQ(back.aperture, sanitized.aperture);
  EXPECT_EQ(back.rightToLeft, sanitized.rightToLeft);
  EXPECT_EQ(back.maxRange, sanitized.maxRange);
  EXPECT_EQ(back.sensorPose, sanitized.sensorPose);
  EXPECT_EQ(back.sensorLabel, "front");
  EXPECT_EQ(back.timestamp, sanitized.timestamp);
  EXPECT_FALSE(back.hasIntensity());
  EXPECT_LT(stored.bytes(), sizeof(StoredScan) + 361 * 4 + 361 / 8 + 64);

  for (const CPose2D& pose : {CPose2D(0, 0, 0), CPose2D(-3.1, 7.2, -2.0)})
  {
    test::expectSameContribution(computeContribution(back, pose, p), computeContribution(sanitized, pose, p));
  }
}
