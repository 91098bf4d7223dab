// movedBeyond: a pose change past a translation or a rotation threshold, angles wrapped.
#include <swslam/geometry/pose_threshold.h>

#include <mrpt/core/bits_math.h>

#include <gtest/gtest.h>

using namespace swslam::geometry;
using mrpt::poses::CPose2D;

TEST(PoseThreshold, MovedBeyondTranslationOrRotation)
{
  const MoveThreshold t{0.1, mrpt::DEG2RAD(1.0)};
  EXPECT_FALSE(movedBeyond(CPose2D(1, 2, 0.3), CPose2D(1.05, 2.05, 0.3), t));
  EXPECT_TRUE(movedBeyond(CPose2D(1, 2, 0.3), CPose2D(1.08, 2.08, 0.3), t));
  EXPECT_FALSE(movedBeyond(CPose2D(0, 0, 0), CPose2D(0, 0, mrpt::DEG2RAD(0.9)), t));
  EXPECT_TRUE(movedBeyond(CPose2D(0, 0, 0), CPose2D(0, 0, mrpt::DEG2RAD(1.1)), t));
  // Angles wrap: 179.8 deg and -179.8 deg are 0.4 deg apart.
  EXPECT_FALSE(movedBeyond(CPose2D(0, 0, mrpt::DEG2RAD(179.8)), CPose2D(0, 0, mrpt::DEG2RAD(-179.8)), t));
}
