#include <swslam/common/unix_time.h>

#include <gtest/gtest.h>

#include <limits>

using namespace swslam::common;

TEST(UnixTime, PlausibleFrom1970To2200)
{
  EXPECT_TRUE(plausibleUnixTime(0));
  EXPECT_TRUE(plausibleUnixTime(1.7e9));
  EXPECT_TRUE(plausibleUnixTime(kLatestPlausibleTime - 1));
  EXPECT_FALSE(plausibleUnixTime(kLatestPlausibleTime));
  EXPECT_FALSE(plausibleUnixTime(-1e-3));
  EXPECT_FALSE(plausibleUnixTime(-1e15));
  EXPECT_FALSE(plausibleUnixTime(1.7e15));
  EXPECT_FALSE(plausibleUnixTime(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(plausibleUnixTime(std::numeric_limits<double>::infinity()));
}

TEST(UnixTime, HintsAtTheUnitOfAStampBeyondTheRange)
{
  EXPECT_EQ(timeUnitHint(1.7e12), " (milliseconds rather than seconds?)");
  EXPECT_EQ(timeUnitHint(1.7e15), " (microseconds rather than seconds?)");
  EXPECT_EQ(timeUnitHint(1.7e18), " (nanoseconds rather than seconds?)");
  EXPECT_EQ(timeUnitHint(1.7e9), "");   // in the range
  EXPECT_EQ(timeUnitHint(-1e15), "");   // no unit explains a negative stamp
  EXPECT_EQ(timeUnitHint(1e30), "");
}
