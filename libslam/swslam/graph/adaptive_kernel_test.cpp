// The adaptive kernel's shape estimate against closed forms and a brute-force likelihood.
#include <swslam/graph/adaptive_kernel.h>
#include <swslam/graph/robust_kernel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using swslam::graph::barronPartition;
using swslam::graph::ShapeEstimator;

namespace
{
/** Norms of 3-D normal residuals of standard deviation sigma (Mahalanobis norms of edges
 * whose information is 1 / sigma^2 too confident when sigma > 1). */
std::vector<double> chi3Residuals(size_t n, double sigma, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> r;
  for (size_t k = 0; k < n; ++k)
  {
    const double a = normal(rng), b = normal(rng), c = normal(rng);
    r.push_back(std::sqrt(a * a + b * b + c * c));
  }
  return r;
}

void addOutliers(std::vector<double>& r, size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> far(20.0, 200.0);
  for (size_t k = 0; k < n; ++k) r.push_back(far(rng));
}

/** The negative log-likelihood per residual, with Z by a fine trapezoid rule. */
double bruteForceNll(const std::vector<double>& r, double alpha, double c, double tau)
{
  const int n = 20000;
  const double h = 2 * tau / n;
  double z = 0;
  for (int i = 0; i <= n; ++i)
    z += (i == 0 || i == n ? 0.5 : 1.0) * std::exp(-swslam::graph::barronRho(-tau + i * h, {alpha, 1.0}));
  z *= h;
  double sum = 0;
  for (const double x : r) sum += swslam::graph::barronRho(std::min(x / c, tau), {alpha, 1.0});
  return sum / static_cast<double>(r.size()) + std::log(z);
}
}  // namespace

TEST(AdaptiveKernel, PartitionMatchesClosedForms)
{
  for (const double tau : {1.0, 10.0, 50.0})
  {
    // alpha = 2: a Gaussian; alpha = 0: 1 / (1 + x^2 / 2), whose integral is an arctangent.
    EXPECT_NEAR(barronPartition(2.0, tau), std::sqrt(2 * M_PI) * std::erf(tau / std::sqrt(2.0)), 1e-9);
    EXPECT_NEAR(barronPartition(0.0, tau), 2 * std::sqrt(2.0) * std::atan(tau / std::sqrt(2.0)), 1e-9);
  }
  // Heavier tails hold more mass: Z grows as alpha falls.
  double last = 0;
  for (double a = 2.0; a >= -10.0; a -= 0.5)
  {
    const double z = barronPartition(a, 10.0);
    EXPECT_GT(z, last) << "alpha " << a;
    last = z;
  }
}

TEST(AdaptiveKernel, InliersGiveLeastSquaresAndOutliersALowShape)
{
  const ShapeEstimator estimator(-10.0, 2.0, 0.1, 10.0);
  std::vector<double> r = chi3Residuals(3000, 1.0, 1);
  EXPECT_DOUBLE_EQ(estimator.estimate(r, 3.0).alpha, 2.0);
  addOutliers(r, 30, 2);  // 1%
  const double one_percent = estimator.estimate(r, 3.0).alpha;
  EXPECT_LT(one_percent, 2.0);
  addOutliers(r, 570, 3);  // 17%
  const double many = estimator.estimate(r, 3.0).alpha;
  EXPECT_LT(many, 0.5);
  EXPECT_LT(many, one_percent);
  EXPECT_DOUBLE_EQ(estimator.estimate({}, 3.0).alpha, 2.0);
  // Within bounds: the clean residuals take the highest shape allowed.
  const ShapeEstimator bounded(-10.0, 0.0, 0.1, 10.0);
  EXPECT_DOUBLE_EQ(bounded.estimate(chi3Residuals(3000, 1.0, 1), 3.0).alpha, 0.0);
  EXPECT_DOUBLE_EQ(bounded.estimate({}, 3.0).alpha, 0.0);
}

TEST(AdaptiveKernel, EstimateIsTheBruteForceArgmin)
{
  const ShapeEstimator estimator(-6.0, 2.0, 0.25, 10.0);
  std::vector<double> r = chi3Residuals(500, 1.3, 4);
  addOutliers(r, 40, 5);
  const double c = 3.0;
  double best_alpha = 0, best = INFINITY;
  for (const double a : estimator.alphas())
  {
    const double nll = bruteForceNll(r, a, c, 10.0);
    if (nll < best) best = nll, best_alpha = a;
  }
  const auto e = estimator.estimate(r, c);
  EXPECT_DOUBLE_EQ(e.alpha, best_alpha);
  EXPECT_NEAR(e.negative_log_likelihood, best, 1e-6);
}

TEST(AdaptiveKernel, RobustScaleOfMahalanobisResiduals)
{
  for (const double sigma : {0.5, 1.0, 2.0})
  {
    std::vector<double> r = chi3Residuals(4000, sigma, 6);
    EXPECT_NEAR(swslam::graph::robustResidualScale(r), sigma, 0.04 * sigma);
    addOutliers(r, 1000, 7);  // 20% far outliers move the median a little
    EXPECT_NEAR(swslam::graph::robustResidualScale(r), sigma, 0.25 * sigma);
  }
  EXPECT_EQ(swslam::graph::robustResidualScale({}), 1.0);
  EXPECT_EQ(swslam::graph::robustResidualScale({0.0, 0.0}), 1e-3);
}

TEST(AdaptiveKernel, TheMemoIsTheEstimatorOfItsGrid)
{
  const ShapeEstimator& a = swslam::graph::shapeEstimatorFor(-4.0, 2.0, 0.5, 10.0);
  EXPECT_EQ(&a, &swslam::graph::shapeEstimatorFor(-4.0, 2.0, 0.5, 10.0));
  EXPECT_EQ(a.alphas().size(), 13u);  // 2, 1.5, ..., -4
  const ShapeEstimator& b = swslam::graph::shapeEstimatorFor(-2.0, 2.0, 0.5, 10.0);
  EXPECT_EQ(b.alphas().size(), 9u);
  EXPECT_EQ(b.alphas().back(), -2.0);
}

TEST(AdaptiveKernel, RejectsBadGrids)
{
  EXPECT_THROW(ShapeEstimator(1.0, 0.0, 0.1, 10.0), std::invalid_argument);
  EXPECT_THROW(ShapeEstimator(-2.0, 2.5, 0.1, 10.0), std::invalid_argument);
  EXPECT_THROW(ShapeEstimator(-INFINITY, 2.0, 0.1, 10.0), std::invalid_argument);
  EXPECT_THROW(ShapeEstimator(-2.0, 2.0, 0.0, 10.0), std::invalid_argument);
  EXPECT_THROW(ShapeEstimator(-2.0, 2.0, 0.1, NAN), std::invalid_argument);
}
