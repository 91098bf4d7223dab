// The search's steady-motion prior (tracking/steady_motion.h).
#include <swslam/tracking/steady_motion.h>

#include <gtest/gtest.h>

using namespace swslam;
using namespace swslam::tracking;
using mrpt::poses::CPose2D;

TEST(SteadyMotion, NoCostUntilEnoughStepsAreKnown)
{
  TrackingParams p;
  SteadyMotion s;
  for (int k = 0; k < 3; k++)
  {
    s.add(CPose2D(1, 0, 0));
    EXPECT_EQ(s.costPerM2(p), 0) << k;
  }
  s.add(CPose2D(1, 0, 0));  // 3 changes now
  EXPECT_GT(s.costPerM2(p), 0);
}

TEST(SteadyMotion, IdenticalStepsGiveTheFloorSigma)
{
  TrackingParams p;
  p.steady_prior_cost = 0.002;
  p.steady_sigma_min = 0.3;
  SteadyMotion s;
  for (int k = 0; k < 10; k++) s.add(CPose2D(1.0, 0.1, 0.05));
  EXPECT_NEAR(s.costPerM2(p), 0.002 / (0.3 * 0.3), 1e-12);
}

TEST(SteadyMotion, SigmaIsTheRmsChangeOfTheLastSixSteps)
{
  TrackingParams p;
  p.steady_prior_cost = 0.01;
  p.steady_sigma_min = 0.01;
  p.steady_min_step = 0.5;
  SteadyMotion s;
  s.add(CPose2D(5, 5, 0));  // forgotten: more than 6 steps ago
  const double xs[] = {1.0, 1.2, 1.0, 1.5, 1.0, 0.9};
  for (double x : xs) s.add(CPose2D(x, 0, 0.3));
  // Changes 0.2, 0.2, 0.5, 0.5, 0.1: mean square (0.04 + 0.04 + 0.25 + 0.25 + 0.01) / 5.
  EXPECT_NEAR(s.costPerM2(p), 0.01 / (0.59 / 5), 1e-12);
}

TEST(SteadyMotion, NoCostWhileSlowOrTurningOnTheSpot)
{
  TrackingParams p;
  SteadyMotion s;
  for (int k = 0; k < 6; k++) s.add(CPose2D(1.0, 0, 0));
  ASSERT_GT(s.costPerM2(p), 0);
  // Three turns on the spot: the last 3 steps average less than steady_min_step.
  for (int k = 0; k < 3; k++) s.add(CPose2D(0.01, 0, 0.7));
  EXPECT_EQ(s.costPerM2(p), 0);
  // Switched off.
  SteadyMotion cruising;
  for (int k = 0; k < 6; k++) cruising.add(CPose2D(1.0, 0, 0));
  p.steady_prior_cost = 0;
  EXPECT_EQ(cruising.costPerM2(p), 0);
}

TEST(SteadyMotion, SigmaIsThatOfThePredictionsMade)
{
  // Steps of 1.0 and 2.0 m in turn (scans at irregular intervals), each predicted exactly at
  // constant velocity: no spread, the floor sigma; judged against the previous step instead,
  // they change by 1 m every time.
  TrackingParams p;
  p.steady_prior_cost = 0.01;
  p.steady_sigma_min = 0.1;
  SteadyMotion exact, per_step;
  for (int k = 0; k < 8; k++)
  {
    const CPose2D motion(k % 2 ? 2.0 : 1.0, 0, 0);
    exact.add(motion, motion);
    per_step.add(motion);
  }
  EXPECT_NEAR(exact.costPerM2(p), 0.01 / (0.1 * 0.1), 1e-12);
  EXPECT_NEAR(per_step.costPerM2(p), 0.01 / 1.0, 1e-12);
}
