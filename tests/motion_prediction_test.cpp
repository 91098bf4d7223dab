// Tracking's constant-velocity prediction (tracking/motion_prediction.h).
#include <swslam/tracking/motion_prediction.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using mrpt::poses::CPose2D;

namespace
{
void expectPose(const CPose2D& a, const CPose2D& b, double tol, const char* what)
{
  EXPECT_NEAR(a.x(), b.x(), tol) << what;
  EXPECT_NEAR(a.y(), b.y(), tol) << what;
  EXPECT_NEAR(std::remainder(a.phi() - b.phi(), 2 * M_PI), 0, tol) << what;
}

/** The slow version: the constant twist integrated in many small steps. */
CPose2D integrated(const CPose2D& m, double s, int n)
{
  // The n-th root of m, found by the same formula at 1/n, is the small step; composing
  // s * n of them must give scaledMotion(m, s) for integer s * n.
  const CPose2D step = scaledMotion(m, 1.0 / n);
  CPose2D out;
  for (int k = 0; k < static_cast<int>(std::lround(s * n)); k++) out = out + step;
  return out;
}
}  // namespace

TEST(MotionPrediction, ScaleOneTwoAndZero)
{
  for (const CPose2D& m : {CPose2D(0.1, 0.02, 0.3), CPose2D(-0.4, 0.3, -2.5), CPose2D(0.2, 0, 0),
                           CPose2D(0, 0, 0.7), CPose2D(0.13, -0.01, 1e-7)})
  {
    expectPose(scaledMotion(m, 1), m, 1e-12, "s = 1");
    expectPose(scaledMotion(m, 2), m + m, 1e-12, "s = 2");
    expectPose(scaledMotion(m, 3), m + m + m, 1e-12, "s = 3");
    expectPose(scaledMotion(m, 0), CPose2D(), 1e-15, "s = 0");
    expectPose(scaledMotion(m, -1), -m, 1e-12, "s = -1");
    const CPose2D half = scaledMotion(m, 0.5);
    expectPose(half + half, m, 1e-12, "s = 1/2 twice");
  }
}

TEST(MotionPrediction, MatchesTheTwistIntegratedInSmallSteps)
{
  // The first-order step (x, y, phi) / n composed n times converges to the same arc.
  const CPose2D m(0.3, 0.1, 0.8);
  for (double s : {0.25, 0.5, 1.5, 2.0})
  {
    const int n = 4000;
    const CPose2D tiny(m.x() / n, m.y() / n, m.phi() / n);  // not from scaledMotion
    CPose2D slow;
    for (int k = 0; k < static_cast<int>(std::lround(s * n)); k++) slow = slow + tiny;
    // m itself is not the integral of (x, y, phi): compare against the integral's own scale.
    CPose2D whole;
    for (int k = 0; k < n; k++) whole = whole + tiny;
    expectPose(scaledMotion(whole, s), slow, 1e-6, "arc");
  }
  expectPose(integrated(m, 1.5, 100), scaledMotion(m, 1.5), 1e-12, "roots compose");
}

TEST(MotionPrediction, ContinuousThroughTheStraightLine)
{
  // The small-angle series and the closed form agree across the switch.
  const CPose2D a = scaledMotion(CPose2D(0.5, 0.1, 0.99e-4), 1.7);
  const CPose2D b = scaledMotion(CPose2D(0.5, 0.1, 1.01e-4), 1.7);
  expectPose(a, b, 1e-5, "series vs closed form");
  expectPose(scaledMotion(CPose2D(0.5, 0.1, 0), 2), CPose2D(1.0, 0.2, 0), 1e-15, "straight");
}

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
