// Covariance of PLICP (paper eq. 4-10): derivatives against numeric ones, and the whole
// estimate against Monte-Carlo runs of the matcher.
#include <swslam/plicp/covariance.h>
#include <swslam/plicp/plicp.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::plicp;

namespace
{
CovarianceTerm sampleTerm(double a_i, double a1, double a2, double r_i, double r1, double r2)
{
  auto dir = [](double a) { return Eigen::Vector2d(std::cos(a), std::sin(a)); };
  return {dir(a_i), dir(a1), dir(a2), r_i, r1, r2, 0, 0, 1};
}

Eigen::Vector3d numericGradient(const CovarianceTerm& t, const Eigen::Vector3d& x)
{
  Eigen::Vector3d g;
  for (int k = 0; k < 3; k++)
  {
    const double h = 1e-6;
    Eigen::Vector3d xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    g(k) = (termCost(t, xp) - termCost(t, xm)) / (2 * h);
  }
  return g;
}
}  // namespace

TEST(PlicpCovariance, HessianOfEq7MatchesNumeric)
{
  const auto t = sampleTerm(0.3, 0.5, 0.52, 4.0, 3.7, 3.8);
  for (const Eigen::Vector3d x : {Eigen::Vector3d(0.2, -0.1, 0.2), Eigen::Vector3d(1, 2, -2.5)})
  {
    const auto d = termDerivatives(t, x);
    for (int k = 0; k < 3; k++)
    {
      const double h = 1e-4;
      Eigen::Vector3d xp = x, xm = x;
      xp(k) += h;
      xm(k) -= h;
      const Eigen::Vector3d col = (numericGradient(t, xp) - numericGradient(t, xm)) / (2 * h);
      for (int r = 0; r < 3; r++) EXPECT_NEAR(d.H(r, k), col(r), 1e-4 * (1 + std::abs(col(r))));
    }
  }
}

TEST(PlicpCovariance, MixedDerivativesOfEq8MatchNumeric)
{
  auto t = sampleTerm(-0.7, -0.2, -0.22, 6.0, 5.5, 5.6);
  const Eigen::Vector3d x(0.3, 0.4, 0.45);
  const auto d = termDerivatives(t, x);
  const double h = 1e-5;
  auto dGrad = [&](double CovarianceTerm::*rho) {
    CovarianceTerm tp = t, tm = t;
    tp.*rho += h;
    tm.*rho -= h;
    return Eigen::Vector3d((numericGradient(tp, x) - numericGradient(tm, x)) / (2 * h));
  };
  const Eigen::Vector3d n_i = dGrad(&CovarianceTerm::rho_i), n_1 = dGrad(&CovarianceTerm::rho_j1),
                        n_2 = dGrad(&CovarianceTerm::rho_j2);
  for (int r = 0; r < 3; r++)
  {
    EXPECT_NEAR(d.d_rho_i(r), n_i(r), 1e-3 * (1 + std::abs(n_i(r))));
    EXPECT_NEAR(d.d_rho_j1(r), n_1(r), 1e-3 * (1 + std::abs(n_1(r))));
    EXPECT_NEAR(d.d_rho_j2(r), n_2(r), 1e-3 * (1 + std::abs(n_2(r))));
  }
}

TEST(PlicpCovariance, AnalyticNormalDerivativeMatchesEq9FiniteDifference)
{
  // Eq. (9) with its step made consistent: the range moves by eps*rho, so the difference is
  // divided by eps*rho (the printed formula divides by eps alone; see doc/plicp.md).
  const auto t = sampleTerm(0.1, 1.0, 1.03, 2.0, 7.0, 7.4);
  Eigen::Matrix2d dC1, dC2;
  normalProjectorDerivatives(t, dC1, dC2);
  auto C = [](const CovarianceTerm& s) {
    const Eigen::Vector2d e = (s.rho_j1 * s.dir_j1 - s.rho_j2 * s.dir_j2).normalized();
    const Eigen::Vector2d n(-e.y(), e.x());
    return Eigen::Matrix2d(n * n.transpose());
  };
  const double eps = 1e-6;
  CovarianceTerm t1 = t, t2 = t;
  t1.rho_j1 += eps * t.rho_j1;
  t2.rho_j2 += eps * t.rho_j2;
  const Eigen::Matrix2d fd1 = (C(t1) - C(t)) / (eps * t.rho_j1);
  const Eigen::Matrix2d fd2 = (C(t2) - C(t)) / (eps * t.rho_j2);
  EXPECT_LT((fd1 - dC1).norm(), 1e-4 * (1 + dC1.norm()));
  EXPECT_LT((fd2 - dC2).norm(), 1e-4 * (1 + dC2.norm()));
}

namespace
{
struct MonteCarlo
{
  Eigen::Matrix3d sample_cov, predicted_cov;
};

/** Matches noisy scans of `world` many times and returns the sample covariance of the
 * result and the mean closed-form prediction. */
MonteCarlo runMonteCarlo(const test::World& world, const mrpt::poses::CPose2D& ref_pose,
                         const mrpt::poses::CPose2D& motion, size_t beams, double fov,
                         double max_range, int runs, double sigma = 0.03)
{
  std::mt19937 rng(2024);
  PlicpParams params;
  params.range_sigma = sigma;
  params.epsilon_xy = 1e-7;
  params.epsilon_theta = 1e-8;
  std::vector<Eigen::Vector3d> xs;
  Eigen::Matrix3d mean_pred = Eigen::Matrix3d::Zero();
  for (int r = 0; r < runs; r++)
  {
    const ReferenceScan ref(sensor::scanFromObservation(
        test::simulateObservation(world, ref_pose, beams, fov, max_range, params.range_sigma, rng)));
    const auto cur = sensor::scanFromObservation(test::simulateObservation(
        world, ref_pose + motion, beams, fov, max_range, params.range_sigma, rng));
    const auto res = matchScans(ref, cur, motion, params);
    EXPECT_TRUE(res.ok()) << res.message;
    xs.emplace_back(res.pose.x(), res.pose.y(), res.pose.phi());
    mean_pred += res.covariance / runs;
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& x : xs) mean += x / xs.size();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& x : xs) cov += (x - mean) * (x - mean).transpose() / (xs.size() - 1);
  return {cov, mean_pred};
}
}  // namespace

TEST(PlicpCovariance, AgreesWithMonteCarloOnAStructuredScene)
{
  // 181 rays over 270 deg: reference points ~10 cm apart at 4 m, well above the 3 cm noise.
  // On denser scans the first-order formula underestimates (doc/plicp.md has the sweep).
  const auto mc = runMonteCarlo(test::roomWorld(), mrpt::poses::CPose2D(-1, 0.5, 0.2),
                                mrpt::poses::CPose2D(0.3, 0.1, 0.05), 181, M_PI * 1.5, 30, 300);
  // Compare in the eigenbasis of the sample covariance: each principal variance within 30%.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(mc.sample_cov);
  for (int k = 0; k < 3; k++)
  {
    const Eigen::Vector3d v = es.eigenvectors().col(k);
    const double sample = es.eigenvalues()(k), predicted = v.dot(mc.predicted_cov * v);
    EXPECT_NEAR(predicted / sample, 1.0, 0.3)
        << "direction " << v.transpose() << ": sample " << sample << " predicted " << predicted;
  }
}

TEST(PlicpCovariance, CorridorAxisIsMuchLessCertain)
{
  std::mt19937 rng(1);
  PlicpParams params;
  const auto world = test::corridorWorld();
  const ReferenceScan ref(sensor::scanFromObservation(
      test::simulateObservation(world, {0, 0, 0}, 181, M_PI, 8, 0.03, rng)));
  const auto cur = sensor::scanFromObservation(
      test::simulateObservation(world, {0.2, 0.05, 0.02}, 181, M_PI, 8, 0.03, rng));
  const auto res = matchScans(ref, cur, mrpt::poses::CPose2D(0.2, 0.05, 0.02), params);
  ASSERT_TRUE(res.ok()) << res.message;
  // Range noise tilts the segment normals, which the first-order formula reads as a little
  // information along the axis: the axis variance is large, not infinite.
  EXPECT_GT(res.covariance(0, 0), 20 * res.covariance(1, 1));
  EXPECT_GT(res.covariance(0, 0), 20 * res.covariance(2, 2));
}


TEST(PlicpCovariance, ResidualVarianceFactorIsTheResidualsNoiseOverTheDatasheets)
{
  // 23 residuals of 6 cm rms less three fitted parameters: 4 times the variance of 3 cm.
  const size_t n = 23;
  const double sum = (n - 3) * 0.06 * 0.06;
  EXPECT_NEAR(plicp::residualVarianceFactor(sum, n, 0.03), 4.0, 1e-12);
  // Residuals within the datasheet's noise do not shrink the covariance.
  EXPECT_EQ(plicp::residualVarianceFactor((n - 3) * 0.01 * 0.01, n, 0.03), 1.0);
  EXPECT_EQ(plicp::residualVarianceFactor(0.0, n, 0.03), 1.0);
  // Three residuals or fewer leave no degree of freedom: no estimate.
  EXPECT_EQ(plicp::residualVarianceFactor(1.0, 3, 0.03), 1.0);
}

TEST(PlicpCovariance, NoisierScansThanTheDatasheetsScaleTheCovarianceByTheFactor)
{
  // Scans with 10 cm noise matched with range_sigma 3 cm: the residuals show the larger
  // noise, and the covariance is the closed form's times their variance factor.
  std::mt19937 rng(4);
  const auto world = test::roomWorld();
  const mrpt::poses::CPose2D ref_pose(-1, 0.5, 0.2), motion(0.3, 0.1, 0.05);
  const ReferenceScan ref(sensor::scanFromObservation(
      test::simulateObservation(world, ref_pose, 181, 1.5 * M_PI, 30, 0.1, rng)));
  const auto cur = sensor::scanFromObservation(
      test::simulateObservation(world, ref_pose + motion, 181, 1.5 * M_PI, 30, 0.1, rng));
  PlicpParams off;
  off.covariance_from_residuals = false;
  PlicpParams on;
  const auto a = matchScans(ref, cur, motion, off), b = matchScans(ref, cur, motion, on);
  ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  EXPECT_EQ(a.variance_factor, 1.0);
  const double f = plicp::residualVarianceFactor(b.sum_sq_residuals, b.correspondences, on.range_sigma);
  EXPECT_GT(f, 3.0);  // (10 cm / 3 cm)^2 = 11 for the current point alone, less after trimming
  EXPECT_EQ(b.variance_factor, f);
  EXPECT_TRUE(b.covariance.isApprox(f * a.covariance, 1e-12));
  EXPECT_TRUE(b.pose == a.pose);
}
