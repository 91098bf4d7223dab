// Reading a run's input: odometry increments between scans, sensor selection, both formats.
#include <swslam/io/scan_source.h>
#include <swslam/io/carmen_log.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/geometry/se2_scaling.h>

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>

#include "test_support.h"

using namespace swslam;
using namespace swslam::io;
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

TEST(OdometryIntegrator, ReadingsAreAlignedWithTheScanTimes)
{
  // 10 Hz readings along an arc at a constant twist; scans 0.066 s and 0.134 s apart in turn
  // (as in MRPT's office rawlog): each increment is the motion between the scans themselves.
  const CPose2D per_second(1.0, 0.0, 0.5);
  auto at = [&](double t) { return geometry::scaledMotion(per_second, t); };
  auto stamp = [](double t) { return mrpt::Clock::fromDouble(100 + t); };
  OdometryIntegrator odo;
  double next_reading = 0, scan = 0.13;  // two readings before the first scan
  for (int k = 0; k < 20; k++)
  {
    while (next_reading <= scan)
    {
      odo.addReading(at(next_reading), stamp(next_reading));
      next_reading += 0.1;
    }
    const auto inc = odo.takeIncrement(stamp(scan));
    const double interval = k % 2 ? 0.134 : 0.066;
    if (k > 0)
    {
      ASSERT_TRUE(inc);
      const CPose2D truth = at(scan) - at(scan - (k % 2 ? 0.066 : 0.134));
      EXPECT_NEAR(inc->x(), truth.x(), 1e-9) << k;
      EXPECT_NEAR(inc->y(), truth.y(), 1e-9) << k;
      EXPECT_NEAR(inc->phi(), truth.phi(), 1e-9) << k;
    }
    scan += interval;
  }
}

TEST(OdometryIntegrator, ExtrapolatesNoFartherThanOneReadingInterval)
{
  OdometryIntegrator odo;
  auto stamp = [](double t) { return mrpt::Clock::fromDouble(100 + t); };
  odo.addReading(CPose2D(0, 0, 0), stamp(0.0));
  odo.addReading(CPose2D(0.1, 0, 0), stamp(0.1));
  EXPECT_FALSE(odo.takeIncrement(stamp(0.1)));  // the first scan
  // Odometry stopped arriving: 1 s later the scan gets one more interval's motion, not ten.
  const auto inc = odo.takeIncrement(stamp(1.1));
  ASSERT_TRUE(inc);
  EXPECT_NEAR(inc->x(), 0.1, 1e-12);
  // Without reading times the last reading is taken as it is.
  OdometryIntegrator untimed;
  untimed.addReading(CPose2D(0, 0, 0));
  untimed.addReading(CPose2D(0.1, 0, 0));
  EXPECT_FALSE(untimed.takeIncrement(stamp(0.5)));
  untimed.addReading(CPose2D(0.3, 0, 0));
  EXPECT_NEAR(untimed.takeIncrement(stamp(0.9))->x(), 0.2, 1e-12);
}

TEST(OdometryIntegrator, AReadingAfterTheScanInterpolates)
{
  // The log holds a reading stamped after the scan before the scan itself.
  auto stamp = [](double t) { return mrpt::Clock::fromDouble(100 + t); };
  OdometryIntegrator odo;
  odo.addReading(CPose2D(0, 0, 0), stamp(0.0));
  odo.addReading(CPose2D(0.1, 0, 0), stamp(0.1));
  EXPECT_FALSE(odo.takeIncrement(stamp(0.05)));  // at 0.05 m
  odo.addReading(CPose2D(0.2, 0, 0), stamp(0.2));
  odo.addReading(CPose2D(0.3, 0, 0), stamp(0.3));
  const auto inc = odo.takeIncrement(stamp(0.25));  // half-way between the last two
  ASSERT_TRUE(inc);
  EXPECT_NEAR(inc->x(), 0.2, 1e-12);
  // A scan stamped three intervals before the last reading: no farther back than one (s = -1).
  odo.addReading(CPose2D(0.4, 0, 0), stamp(0.4));
  odo.addReading(CPose2D(0.5, 0, 0), stamp(0.5));
  EXPECT_NEAR(odo.takeIncrement(stamp(0.2))->x(), 0.4 - 0.25, 1e-12);
}

TEST(OdometryIntegrator, ReadingsOutOfOrderOrRepeatedDoNotMoveItBack)
{
  auto stamp = [](double t) { return mrpt::Clock::fromDouble(100 + t); };
  OdometryIntegrator odo;
  odo.addReading(CPose2D(0, 0, 0), stamp(0.0));
  odo.addReading(CPose2D(0.1, 0, 0), stamp(0.1));
  EXPECT_FALSE(odo.takeIncrement(stamp(0.1)));
  odo.addReading(CPose2D(0.2, 0, 0), stamp(0.2));
  odo.addReading(CPose2D(0.05, 0, 0), stamp(0.05));  // late: ignored
  EXPECT_NEAR(odo.takeIncrement(stamp(0.2))->x(), 0.1, 1e-12);
  odo.addReading(CPose2D(0.21, 0, 0), stamp(0.2));  // same time: replaces the last reading
  odo.addReading(CPose2D(0.31, 0, 0), stamp(0.3));
  // The interval stays 0.2 -> 0.3 (0.1 m per 0.1 s): at 0.35 s, 0.36 m.
  EXPECT_NEAR(odo.takeIncrement(stamp(0.35))->x(), 0.36 - 0.2, 1e-12);
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
  sensor::ScanInput in;
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
  sensor::ScanInput in;
  EXPECT_FALSE(src->next(in));
  EXPECT_EQ(src->stats().scans, 0u);
  EXPECT_GT(src->stats().otherSensors(), 2000u);
  // By label, and named when nothing of the asked sensor was found.
  ASSERT_EQ(src->stats().other_labels.size(), 1u);
  const auto& [label, count] = *src->stats().other_labels.begin();
  EXPECT_EQ(count, src->stats().otherSensors());
  const std::string why = noScanReason(src->stats(), "NO_SUCH_LASER");
  EXPECT_NE(why.find("no scan of sensor 'NO_SUCH_LASER'"), std::string::npos) << why;
  EXPECT_NE(why.find("'" + label + "' (" + std::to_string(count) + " scans)"), std::string::npos) << why;
  ScanSourceStats none;
  none.odometry = 4;
  EXPECT_NE(noScanReason(none, "").find("no laser scan"), std::string::npos);
  none.scans = 1;
  EXPECT_EQ(noScanReason(none, ""), "");
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

TEST(ScanSource, APipeOrADeviceIsAnErrorNotAWait)
{
  // A FIFO with no writer would block the open for ever (and a signal would not end it).
  const std::string fifo = test::tempDir("scan_source_fifo") + "/input.log";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, std::string("/dev/null")})
  {
    try
    {
      openScanSource(path, ScanSourceOptions{}, CarmenParams());
      FAIL() << path << ": no error";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("'" + path + "' is not a file but a pipe, socket or device"), std::string::npos)
          << e.what();
    }
  }
  // The readers themselves refuse it too (swslam-carmen2rawlog reads a log without a source).
  EXPECT_THROW(CarmenLogReader(fifo, CarmenParams()), std::runtime_error);
  EXPECT_THROW(RawlogReader{fifo}, std::runtime_error);
}

TEST(ScanSource, ACarmenLogWithNegativeStampsSaysItsShift)
{
  const std::string log = test::tempDir("scan_source_negative") + "/negative.log";
  std::ofstream(log) << "FLASER 5 1 1 1 1 1 0 0 0 0 0 0 -10.5 host -10.5\n"
                        "FLASER 5 1 1 1 1 1 0 0 0 0 0 0 -10.0 host -10.0\n";
  const auto source = openScanSource(log, ScanSourceOptions{}, CarmenParams());
  EXPECT_NE(source->describe().find("timestamps shifted by +10.500000 s (the log's laser stamps are negative)"),
            std::string::npos)
      << source->describe();
}
