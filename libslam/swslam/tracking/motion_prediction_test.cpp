// Tracking's constant-velocity prediction: the interval ratio (tracking/motion_prediction.h);
// the scaling itself is in se2_scaling_test.cpp.
#include <swslam/tracking/motion_prediction.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::tracking;

TEST(MotionPrediction, IntervalRatioGuards)
{
  EXPECT_DOUBLE_EQ(intervalRatio(0.1, 0.05, 4, 1), 2.0);
  EXPECT_DOUBLE_EQ(intervalRatio(0.05, 0.1, 4, 1), 0.5);
  EXPECT_DOUBLE_EQ(intervalRatio(0.0, 0.1, 4, 1), 1.0);    // repeated stamp
  EXPECT_DOUBLE_EQ(intervalRatio(0.1, -0.1, 4, 1), 1.0);   // backwards
  EXPECT_DOUBLE_EQ(intervalRatio(std::nan(""), 0.1, 4, 1), 1.0);
}

TEST(MotionPrediction, AGapOfDroppedScansIsPredictedInFullAndTheScanAfterItToo)
{
  // 18 Hz scans with eight dropped (0.43 s): well within the second a vehicle's speed holds.
  EXPECT_DOUBLE_EQ(intervalRatio(0.43, 0.054, 4, 1), 0.43 / 0.054);
  EXPECT_DOUBLE_EQ(intervalRatio(0.054, 0.43, 4, 1), 0.054 / 0.43);
  // Beyond the horizon: over at most the horizon, or max_ratio times the last interval.
  EXPECT_DOUBLE_EQ(intervalRatio(10.0, 0.1, 4, 1), 10.0);      // 1 s of motion
  EXPECT_DOUBLE_EQ(intervalRatio(10.0, 0.5, 4, 1), 4.0);       // 2 s: max_ratio
  EXPECT_DOUBLE_EQ(intervalRatio(0.001, 0.1, 4, 1), 0.01);     // both within the horizon
  EXPECT_DOUBLE_EQ(intervalRatio(1.0, 12.0, 4, 1), 0.25);      // a 12 s gap's mean motion
  EXPECT_DOUBLE_EQ(intervalRatio(0.5, 12.0, 4, 0.25), 0.25);
}
