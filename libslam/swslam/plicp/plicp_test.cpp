// The PLICP matcher end to end on small synthetic worlds.
#include <swslam/plicp/plicp.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::plicp;

namespace
{
struct Case
{
  test::World world;
  mrpt::poses::CPose2D ref_pose, motion;
  size_t beams;
  double fov, max_range;
};

MatchResult run(const Case& c, const mrpt::poses::CPose2D& guess, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  const ReferenceScan ref(sensor::scanFromObservation(
      test::simulateObservation(c.world, c.ref_pose, c.beams, c.fov, c.max_range, 0.03, rng)));
  const auto cur = sensor::scanFromObservation(test::simulateObservation(
      c.world, c.ref_pose + c.motion, c.beams, c.fov, c.max_range, 0.03, rng));
  return matchScans(ref, cur, guess, PlicpParams());
}

void expectNear(const MatchResult& r, const mrpt::poses::CPose2D& truth, double tol_xy,
                double tol_deg)
{
  ASSERT_TRUE(r.ok()) << toString(r.status) << ": " << r.message;
  EXPECT_NEAR(r.pose.x(), truth.x(), tol_xy);
  EXPECT_NEAR(r.pose.y(), truth.y(), tol_xy);
  EXPECT_NEAR(std::remainder(r.pose.phi() - truth.phi(), 2 * M_PI) * 180 / M_PI, 0, tol_deg);
}
}  // namespace

TEST(Plicp, RecoversMotionInARoomFromIdentityAndFromTruth)
{
  const Case c{test::roomWorld(), {-2, 1, 0.3}, {0.4, -0.2, 0.12}, 361, 1.5 * M_PI, 30};
  expectNear(run(c, {}), c.motion, 0.02, 0.3);
  expectNear(run(c, c.motion), c.motion, 0.02, 0.3);
}

TEST(Plicp, RecoversMotionInClutterWith1081Beams)
{
  const Case c{test::clutteredWorld(3), {0, -3, 0.1}, {0.35, 0.05, 0.08}, 1081, 1.5 * M_PI, 30};
  const auto r = run(c, {});
  expectNear(r, c.motion, 0.03, 0.3);
  EXPECT_GT(r.correspondences, 200u);
  EXPECT_GT(r.sum_sq_residuals, 0);
  EXPECT_LT(r.iterations, PlicpParams().max_iterations);
}

TEST(Plicp, WorksOnFullCircleScans)
{
  const double fov = 2 * M_PI * 719.0 / 720.0;
  const Case c{test::roomWorld(), {1, -1, -2.8}, {-0.3, 0.3, -0.1}, 720, fov, 30};
  expectNear(run(c, {}), c.motion, 0.02, 0.3);
}

TEST(Plicp, CovarianceIsSymmetricPositiveDefinite)
{
  const Case c{test::roomWorld(), {-2, 1, 0.3}, {0.4, -0.2, 0.12}, 361, 1.5 * M_PI, 30};
  const auto r = run(c, c.motion);
  ASSERT_TRUE(r.ok());
  EXPECT_LT((r.covariance - r.covariance.transpose()).norm(), 1e-12);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(r.covariance);
  EXPECT_GT(es.eigenvalues().minCoeff(), 0);
}

TEST(Plicp, EmptyAndAllInvalidScansFailWithAMessage)
{
  std::mt19937 rng(1);
  const auto world = test::roomWorld();
  auto obs = test::simulateObservation(world, {}, 181, M_PI, 30, 0.0, rng);
  const ReferenceScan ref(sensor::scanFromObservation(obs));
  for (size_t i = 0; i < obs.getScanSize(); i++) obs.setScanRangeValidity(i, false);
  const auto r = matchScans(ref, sensor::scanFromObservation(obs), {}, PlicpParams());
  EXPECT_EQ(r.status, MatchStatus::TooFewCorrespondences);
  EXPECT_NE(r.message.find("valid rays"), std::string::npos) << r.message;
  EXPECT_FALSE(r.ok());
}

TEST(Plicp, NonFiniteAndNegativeRangesAreDroppedBeforeMatching)
{
  std::mt19937 rng(2);
  const auto world = test::roomWorld();
  const auto obs = test::simulateObservation(world, {}, 361, 1.5 * M_PI, 30, 0.01, rng);
  auto bad = test::simulateObservation(world, {0.2, 0, 0.05}, 361, 1.5 * M_PI, 30, 0.01, rng);
  for (size_t i = 0; i < bad.getScanSize(); i += 3)
  {
    bad.setScanRange(i, i % 2 ? std::numeric_limits<float>::quiet_NaN() : -5.0f);
    bad.setScanRangeValidity(i, true);
  }
  const auto r = matchScans(ReferenceScan(sensor::scanFromObservation(obs)), sensor::scanFromObservation(bad), {},
                            PlicpParams());
  expectNear(r, {0.2, 0, 0.05}, 0.02, 0.3);
}

TEST(Plicp, ScansFromDifferentSensorsAreRejected)
{
  std::mt19937 rng(3);
  const auto world = test::roomWorld();
  const ReferenceScan ref(
      sensor::scanFromObservation(test::simulateObservation(world, {}, 361, M_PI, 30, 0.0, rng)));
  auto other = test::simulateObservation(world, {}, 181, M_PI, 30, 0.0, rng);
  other.sensorLabel = "REAR_LASER";
  const auto r = matchScans(ref, sensor::scanFromObservation(other), {}, PlicpParams());
  EXPECT_EQ(r.status, MatchStatus::InvalidInput);
  EXPECT_NE(r.message.find("different sensors"), std::string::npos) << r.message;
}

TEST(Plicp, AWildResultIsReportedAsDiverged)
{
  const Case c{test::roomWorld(), {-2, 1, 0.3}, {0.4, -0.2, 0.12}, 361, 1.5 * M_PI, 30};
  PlicpParams p;
  p.max_correction_xy = 0.05;  // the true motion is farther than this from the guess
  std::mt19937 rng(1);
  const ReferenceScan ref(sensor::scanFromObservation(
      test::simulateObservation(c.world, c.ref_pose, c.beams, c.fov, c.max_range, 0.03, rng)));
  const auto cur = sensor::scanFromObservation(test::simulateObservation(
      c.world, c.ref_pose + c.motion, c.beams, c.fov, c.max_range, 0.03, rng));
  EXPECT_EQ(matchScans(ref, cur, {}, p).status, MatchStatus::Diverged);
}

