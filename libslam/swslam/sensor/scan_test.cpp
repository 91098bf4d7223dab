#include <swslam/sensor/scan.h>

#include <gtest/gtest.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <limits>

using swslam::sensor::rotationLength;
using swslam::sensor::scanFromObservation;

namespace
{
mrpt::obs::CObservation2DRangeScan makeObs(size_t n, double aperture, bool right_to_left = true)
{
  mrpt::obs::CObservation2DRangeScan o;
  o.aperture = static_cast<float>(aperture);
  o.maxRange = 30.0f;
  o.rightToLeft = right_to_left;
  o.resizeScan(n);
  for (size_t i = 0; i < n; i++)
  {
    o.setScanRange(i, 5.0f);
    o.setScanRangeValidity(i, true);
  }
  return o;
}
}  // namespace

TEST(Scan, KeepsOnlyValidRaysAndCountsReasons)
{
  auto o = makeObs(8, M_PI);
  o.setScanRangeValidity(0, false);
  o.setScanRange(1, std::numeric_limits<float>::quiet_NaN());
  o.setScanRange(2, -1.0f);
  o.setScanRange(3, 0.0f);
  o.setScanRange(4, 30.0f);  // max range = no return
  o.setScanRange(5, 0.05f);  // below min range
  const auto s = scanFromObservation(o, 0.1);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.rejected.flagged_invalid, 1u);
  EXPECT_EQ(s.rejected.not_finite, 1u);
  EXPECT_EQ(s.rejected.non_positive, 2u);
  EXPECT_EQ(s.rejected.at_or_above_max, 1u);
  EXPECT_EQ(s.rejected.below_min, 1u);
  EXPECT_EQ(s.beam_index[0], 6);
  EXPECT_EQ(s.beam_index[1], 7);
}

TEST(Scan, AnglesAndPointsForAnyFov)
{
  for (double fov_deg : {180.0, 270.0, 360.0})
  {
    for (size_t n : {180u, 181u, 361u, 1081u})
    {
      const double fov = fov_deg * M_PI / 180;
      const auto s = scanFromObservation(makeObs(n, fov));
      ASSERT_EQ(s.size(), n);
      EXPECT_NEAR(s.angles.front(), -fov / 2, 1e-6);
      EXPECT_NEAR(s.angles.back(), fov / 2, 1e-6);
      for (size_t i = 1; i < n; i++) ASSERT_GT(s.angles[i], s.angles[i - 1]);
      for (size_t i = 0; i < n; i++)
      {
        EXPECT_NEAR(s.points[i].x(), 5 * std::cos(s.angles[i]), 1e-5);
        EXPECT_NEAR(s.points[i].y(), 5 * std::sin(s.angles[i]), 1e-5);
      }
    }
  }
}

TEST(Scan, LeftToRightScansAreReorderedByIncreasingAngle)
{
  auto o = makeObs(5, M_PI / 2, /*right_to_left=*/false);
  o.setScanRange(0, 1.0f);  // first beam is the leftmost (+45 deg)
  const auto s = scanFromObservation(o);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_NEAR(s.angles.back(), M_PI / 4, 1e-6);
  EXPECT_EQ(s.beam_index.back(), 0);
  EXPECT_NEAR(s.ranges.back(), 1.0, 1e-6);
  for (size_t i = 0; i < s.size(); i++)
  {
    EXPECT_NEAR(s.points[i].x(), s.ranges[i] * std::cos(s.angles[i]), 1e-5);
    EXPECT_NEAR(s.points[i].y(), s.ranges[i] * std::sin(s.angles[i]), 1e-5);
  }
}

TEST(Scan, RejectsInconsistentGeometryWithAMessage)
{
  EXPECT_THROW(scanFromObservation(makeObs(1, M_PI)), std::invalid_argument);
  EXPECT_THROW(scanFromObservation(makeObs(10, 0.0)), std::invalid_argument);
  EXPECT_THROW(scanFromObservation(makeObs(10, 7.0)), std::invalid_argument);
  try
  {
    scanFromObservation(makeObs(0, M_PI));
    FAIL();
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("beams"), std::string::npos);
  }
}

TEST(Scan, AllInvalidGivesEmptyScan)
{
  auto o = makeObs(20, M_PI);
  for (size_t i = 0; i < 20; i++) o.setScanRangeValidity(i, false);
  const auto s = scanFromObservation(o);
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.rejected.total(), 20u);
}

TEST(Scan, RejectsASensorPoseThatIsNotFinite)
{
  // A corrupt rawlog entry can carry a NaN in the sensor pose's translation or rotation.
  for (int entry : {3, 0})  // x, then the rotation's first entry
  {
    auto o = makeObs(10, M_PI);
    auto m = o.sensorPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
    m(0, entry) = std::numeric_limits<double>::quiet_NaN();
    o.sensorPose = mrpt::poses::CPose3D(m);
    try
    {
      swslam::sensor::checkObservationGeometry(o);
      FAIL() << "entry " << entry;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find("sensor pose"), std::string::npos) << e.what();
    }
    EXPECT_THROW(scanFromObservation(o), std::invalid_argument);
  }
}

TEST(Scan, CheckedConversionEqualsTheCheckingOneAndOnlyTheCheckingOneThrows)
{
  mrpt::obs::CObservation2DRangeScan obs;
  obs.aperture = M_PI;
  obs.maxRange = 10;
  obs.resizeScan(5);
  for (size_t i = 0; i < 5; i++) obs.setScanRange(i, 1.0f + i), obs.setScanRangeValidity(i, true);
  const swslam::sensor::Scan a = swslam::sensor::scanFromObservation(obs);
  const swslam::sensor::Scan b = swslam::sensor::scanFromCheckedObservation(obs);
  EXPECT_EQ(a.ranges, b.ranges);
  EXPECT_EQ(a.angles, b.angles);
  obs.aperture = 0;
  EXPECT_THROW(swslam::sensor::checkObservationGeometry(obs), std::invalid_argument);
  EXPECT_THROW(swslam::sensor::scanFromObservation(obs), std::invalid_argument);
}

TEST(Scan, RotationLengthIsTheRootMeanSquareRange)
{
  EXPECT_NEAR(rotationLength({{3, 4}, {0, 5}}), 5, 1e-12);
  EXPECT_NEAR(rotationLength({{1, 0}, {0, 7}}), 5, 1e-12);
  EXPECT_EQ(rotationLength({}), 1) << "no points";
  EXPECT_EQ(rotationLength({{0, 0}}), 1) << "all at the sensor";
}
