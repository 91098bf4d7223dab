// A relative motion held for a different time at the same twist (se2_scaling.h).
#include <swslam/geometry/se2_scaling.h>

#include <swslam/geometry/expect_pose.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::geometry;
using mrpt::poses::CPose2D;

TEST(SE2Scaling, WholeMultiplesAreCompositions)
{
  // Including turns near +-pi, where the turn of s m wraps.
  for (const CPose2D& m : {CPose2D(0.1, 0.02, 0.3), CPose2D(-0.4, 0.3, -2.5), CPose2D(0.2, 0, 0),
                           CPose2D(0, 0, 0.7), CPose2D(0.13, -0.01, 1e-7), CPose2D(0.5, -0.2, 3.1),
                           CPose2D(0.3, 0.4, -3.1)})
  {
    expectPose(scaledMotion(m, 1), m, 1e-12, "s = 1");
    expectPose(scaledMotion(m, 2), m + m, 1e-12, "s = 2");
    expectPose(scaledMotion(m, 3), m + m + m, 1e-12, "s = 3");
    expectPose(scaledMotion(m, 4), m + m + m + m, 1e-12, "s = 4");
    expectPose(scaledMotion(m, 0), CPose2D(), 1e-15, "s = 0");
    expectPose(scaledMotion(m, -1), -m, 1e-12, "s = -1");
    expectPose(scaledMotion(m, -2), -(m + m), 1e-12, "s = -2");
  }
}

TEST(SE2Scaling, FractionsComposeBackToTheMotion)
{
  for (const CPose2D& m : {CPose2D(0.1, 0.02, 0.3), CPose2D(0.5, -0.2, 3.1), CPose2D(0.3, 0.4, -3.1)})
  {
    const CPose2D half = scaledMotion(m, 0.5);
    expectPose(half + half, m, 1e-12, "two halves");
    const CPose2D third = scaledMotion(m, 1.0 / 3);
    expectPose(third + third + third, m, 1e-12, "three thirds");
    expectPose(scaledMotion(m, -0.5) + scaledMotion(m, 0.5), CPose2D(), 1e-12, "back and forth");
    expectPose(scaledMotion(m, 1.5), m + half, 1e-12, "one and a half");
  }
}

TEST(SE2Scaling, MatchesTheTwistIntegratedInSmallSteps)
{
  // The slow version: a tiny step composed k times moves along one arc at one twist, so
  // scaling the result of n steps by s must give the result of s n steps.
  const CPose2D m(0.3, 0.1, 0.8);
  const int n = 4000;
  const CPose2D tiny(m.x() / n, m.y() / n, m.phi() / n);  // not from scaledMotion
  CPose2D whole;
  for (int k = 0; k < n; k++) whole = whole + tiny;
  for (double s : {0.25, 0.5, 1.5, 2.0})
  {
    CPose2D slow;
    for (int k = 0; k < static_cast<int>(std::lround(s * n)); k++) slow = slow + tiny;
    expectPose(scaledMotion(whole, s), slow, 1e-6, "arc");
  }
}

TEST(SE2Scaling, ContinuousThroughTheStraightLine)
{
  // The small-angle series and the closed form agree across the switch.
  const CPose2D a = scaledMotion(CPose2D(0.5, 0.1, 0.99e-4), 1.7);
  const CPose2D b = scaledMotion(CPose2D(0.5, 0.1, 1.01e-4), 1.7);
  expectPose(a, b, 1e-5, "series vs closed form");
  expectPose(scaledMotion(CPose2D(0.5, 0.1, 0), 2), CPose2D(1.0, 0.2, 0), 1e-15, "straight");
}
