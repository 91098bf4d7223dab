// Reading a run's input: odometry increments between scans, sensor selection, both formats.
#include <swslam/system/scan_source.h>

#include <gtest/gtest.h>

using namespace swslam;
using mrpt::poses::CPose2D;

TEST(OdometryIntegrator, AbsoluteReadingsBecomeIncrementsInTheVehicleFrame)
{
  OdometryIntegrator odo;
  EXPECT_FALSE(odo.takeIncrement());  // nothing yet
  odo.addReading(CPose2D(1, 1, M_PI / 2));
  EXPECT_FALSE(odo.takeIncrement());  // first scan: no previous reading to compare with
  odo.addReading(CPose2D(1, 2, M_PI / 2));  // 1 m forward along +y = vehicle x
  const auto inc = odo.takeIncrement();
  ASSERT_TRUE(inc);
  EXPECT_NEAR(inc->x(), 1, 1e-12);
  EXPECT_NEAR(inc->y(), 0, 1e-12);
  EXPECT_NEAR(inc->phi(), 0, 1e-12);
  // No new reading: the motion since the last scan is zero, not unknown.
  const auto still = odo.takeIncrement();
  ASSERT_TRUE(still);
  EXPECT_NEAR(still->norm(), 0, 1e-12);
}

TEST(OdometryIntegrator, ActionsAccumulateUntilTheNextScan)
{
  OdometryIntegrator odo;
  odo.addIncrement(CPose2D(1, 0, M_PI / 2));
  odo.addIncrement(CPose2D(1, 0, 0));
  const auto inc = odo.takeIncrement();
  ASSERT_TRUE(inc);
  EXPECT_NEAR(inc->x(), 1, 1e-12);
  EXPECT_NEAR(inc->y(), 1, 1e-12);
  EXPECT_NEAR(inc->phi(), M_PI / 2, 1e-12);
  EXPECT_FALSE(odo.takeIncrement());  // no action since
}

TEST(ScanSource, ReadsTheBundledRawlogWithItsOdometry)
{
  auto src = openScanSource(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog",
                            ScanSourceOptions{}, CarmenParams());
  ScanInput in;
  size_t n = 0, with_odometry = 0;
  while (n < 50 && src->next(in))
  {
    ASSERT_TRUE(in.observation);
    n++;
    with_odometry += in.odometry_increment.has_value();
  }
  EXPECT_EQ(n, 50u);
  EXPECT_GE(with_odometry, 48u);
  EXPECT_GT(src->fractionRead(), 0.0);
  EXPECT_LT(src->fractionRead(), 0.5);

  auto laser_only = openScanSource(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog",
                                   ScanSourceOptions{false, ""}, CarmenParams());
  ASSERT_TRUE(laser_only->next(in));
  ASSERT_TRUE(laser_only->next(in));
  EXPECT_FALSE(in.odometry_increment);
}

TEST(ScanSource, OtherSensorsAreSkippedAndCounted)
{
  auto src = openScanSource(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog",
                            ScanSourceOptions{true, "NO_SUCH_LASER"}, CarmenParams());
  ScanInput in;
  EXPECT_FALSE(src->next(in));
  EXPECT_EQ(src->stats().scans, 0u);
  EXPECT_GT(src->stats().other_sensors, 2000u);
}

TEST(ScanSource, MissingFileIsAnErrorNamingIt)
{
  try
  {
    openScanSource("/nonexistent/x.rawlog", ScanSourceOptions{}, CarmenParams());
    FAIL() << "no error";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.rawlog"), std::string::npos);
  }
}
