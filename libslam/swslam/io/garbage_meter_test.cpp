// GarbageMeter: when the bytes a driver read without a scan become garbage, and how many.
#include <swslam/io/garbage_meter.h>

#include <gtest/gtest.h>

namespace swslam::io
{
namespace
{
TEST(GarbageMeter, ScansAndSmallRepliesWithoutAScanAreNotGarbage)
{
  GarbageMeter m(1000);
  m.connected(300);                          // start-up replies
  EXPECT_FALSE(m.noScan(300, 322, false));   // a reply without a scan (the MD acknowledgement)
  m.scan(3700);
  EXPECT_FALSE(m.noScan(3700, 3700, false));  // silence
  EXPECT_FALSE(m.noScan(3700, 4500, false));  // a rejected scan, under the threshold
  m.scan(7800);
  EXPECT_FALSE(m.noScan(7800, 7800, true));   // cut while silent: nothing was read
  EXPECT_EQ(m.bytes(), 0u);
}

TEST(GarbageMeter, MoreThanTheThresholdWithoutAScanIsGarbageFromTheLastScan)
{
  GarbageMeter m(1000);
  m.connected(0);
  m.scan(3400);
  EXPECT_FALSE(m.noScan(3400, 4000, false));
  EXPECT_TRUE(m.noScan(4000, 4401, false));   // 1001 bytes since the scan
  EXPECT_EQ(m.bytes(), 1001u);
  EXPECT_FALSE(m.noScan(4401, 9000, false));  // said once per stretch, counted on
  EXPECT_EQ(m.bytes(), 5600u);
  EXPECT_EQ(m.sinceScan(9000), 5600u);
  m.scan(12400);                        // the sensor again: that stretch ends uncounted
  EXPECT_EQ(m.bytes(), 5600u);
  EXPECT_FALSE(m.noScan(12400, 12500, false));
  EXPECT_TRUE(m.noScan(12500, 12600, true));  // a call cut while reading: garbage at once
  EXPECT_EQ(m.bytes(), 5800u);
}

TEST(GarbageMeter, CountsAcrossConnections)
{
  GarbageMeter m(1000);
  m.connected(0);
  EXPECT_TRUE(m.noScan(0, 68000, false));  // from the start
  m.connected(0);                          // a new stream counts from 0 again
  EXPECT_FALSE(m.noScan(0, 500, false));
  EXPECT_TRUE(m.noScan(500, 2000, true));
  EXPECT_EQ(m.bytes(), 70000u);
}

}  // namespace
}  // namespace swslam::io
