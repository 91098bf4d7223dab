// Tracking's constant-velocity prediction: the interval ratio (tracking/motion_prediction.h);
// the scaling itself is in se2_scaling_test.cpp.
#include <swslam/tracking/motion_prediction.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::tracking;

TEST(MotionPrediction, IntervalRatioGuards)
{
  EXPECT_DOUBLE_EQ(intervalRatio(0.1, 0.05, 4), 2.0);
  EXPECT_DOUBLE_EQ(intervalRatio(0.05, 0.1, 4), 0.5);
  EXPECT_DOUBLE_EQ(intervalRatio(10.0, 0.1, 4), 4.0);   // a gap in the log
  EXPECT_DOUBLE_EQ(intervalRatio(0.001, 0.1, 4), 0.25);
  EXPECT_DOUBLE_EQ(intervalRatio(0.0, 0.1, 4), 1.0);    // repeated stamp
  EXPECT_DOUBLE_EQ(intervalRatio(0.1, -0.1, 4), 1.0);   // backwards
  EXPECT_DOUBLE_EQ(intervalRatio(std::nan(""), 0.1, 4), 1.0);
}
