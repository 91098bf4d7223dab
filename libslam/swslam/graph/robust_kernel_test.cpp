// Barron's kernel against the closed forms of its named special cases and against a
// numeric derivative of rho.
#include <swslam/graph/robust_kernel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace swslam;
using namespace swslam::graph;

namespace
{
const double kResiduals[] = {0.0, 1e-6, 0.1, 0.7, 1.0, 2.5, 10.0, 1e3};
const double kScales[] = {0.5, 1.0, 3.0};

void expectRelNear(double a, double b, double rel)
{
  EXPECT_NEAR(a, b, rel * std::max(1.0, std::abs(b)));
}
}  // namespace

TEST(RobustKernel, MatchesClosedFormsOfNamedKernels)
{
  for (double c : kScales)
    for (double r : kResiduals)
    {
      const double z = (r / c) * (r / c);
      expectRelNear(barronRho(r, {2.0, c}), 0.5 * z, 1e-14);                       // L2
      expectRelNear(barronRho(r, {1.0, c}), std::sqrt(z + 1.0) - 1.0, 1e-12);      // L1-like
      expectRelNear(barronRho(r, {0.0, c}), std::log(0.5 * z + 1.0), 1e-14);       // Cauchy
      expectRelNear(barronRho(r, {-2.0, c}), 2.0 * z / (z + 4.0), 1e-12);          // Geman-McClure
      expectRelNear(barronRho(r, {swslam::graph::kAlphaWelsch, c}), 1.0 - std::exp(-0.5 * z), 1e-14);

      // Weights rho'(r)/r of the same kernels, in closed form.
      const double ic2 = 1.0 / (c * c);
      expectRelNear(barronWeight(r, {2.0, c}), ic2, 1e-14);
      expectRelNear(barronWeight(r, {1.0, c}), ic2 / std::sqrt(z + 1.0), 1e-12);
      expectRelNear(barronWeight(r, {0.0, c}), ic2 / (0.5 * z + 1.0), 1e-12);
      expectRelNear(barronWeight(r, {-2.0, c}), ic2 * 16.0 / ((z + 4.0) * (z + 4.0)), 1e-12);
      expectRelNear(barronWeight(r, {swslam::graph::kAlphaWelsch, c}), ic2 * std::exp(-0.5 * z), 1e-12);
    }
}

TEST(RobustKernel, DerivativeMatchesNumericDerivativeOfRho)
{
  for (double alpha : {2.0, 1.9, 1.5, 1.0, 0.5, 1e-3, 0.0, -0.5, -2.0, -7.0, -100.0,
                       swslam::graph::kAlphaWelsch})
    for (double c : kScales)
      for (double r : {0.05, 0.3, 1.0, 2.0, 5.0, 20.0})
      {
        const BarronKernel k{alpha, c};
        const double h = 1e-6 * std::max(1.0, r);
        const double numeric = (barronRho(r + h, k) - barronRho(r - h, k)) / (2 * h);
        EXPECT_NEAR(barronRhoDerivative(r, k), numeric, 1e-6 * std::max(1.0, std::abs(numeric)))
            << "alpha " << alpha << " c " << c << " r " << r;
        EXPECT_NEAR(barronWeight(r, k), barronRhoDerivative(r, k) / r, 1e-12);
      }
}

TEST(RobustKernel, GeneralFormulaTendsToTheExactLimits)
{
  // Near alpha = 2, 0 and -inf the general formula must approach the special cases.
  for (double r : {0.3, 1.0, 4.0})
  {
    EXPECT_NEAR(barronRho(r, {2.0 - 1e-9, 1.0}), barronRho(r, {2.0, 1.0}), 1e-6);
    EXPECT_NEAR(barronRho(r, {1e-9, 1.0}), barronRho(r, {0.0, 1.0}), 1e-6);
    EXPECT_NEAR(barronRho(r, {-1e-9, 1.0}), barronRho(r, {0.0, 1.0}), 1e-6);
    EXPECT_NEAR(barronRho(r, {-1e7, 1.0}), barronRho(r, {swslam::graph::kAlphaWelsch, 1.0}), 1e-5);
    EXPECT_NEAR(barronWeight(r, {2.0 - 1e-9, 1.0}), 1.0, 1e-6);
  }
}

TEST(RobustKernel, SmallResidualsWeighOneAfterNormalization)
{
  for (double alpha : {1.0, 0.0, -2.0, swslam::graph::kAlphaWelsch})
  {
    EXPECT_NEAR(normalizedBarronWeight(1e-8, {alpha, 3.0}), 1.0, 1e-12);
    EXPECT_NEAR(normalizedBarronRho(1e-3, {alpha, 3.0}), 0.5e-6, 1e-12);
    // Robust kernels down-weight outliers; a large residual weighs far less than 1.
    EXPECT_LT(normalizedBarronWeight(100.0, {alpha, 3.0}), 0.05);
  }
}

TEST(RobustKernel, RejectsInvalidShapeOrScale)
{
  EXPECT_THROW(swslam::graph::checkKernel({2.5, 1.0}), std::invalid_argument);
  EXPECT_THROW(swslam::graph::checkKernel({NAN, 1.0}), std::invalid_argument);
  EXPECT_THROW(swslam::graph::checkKernel({0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(swslam::graph::checkKernel({0.0, -1.0}), std::invalid_argument);
  EXPECT_THROW(swslam::graph::checkKernel({0.0, INFINITY}), std::invalid_argument);
  EXPECT_NO_THROW(swslam::graph::checkKernel({swslam::graph::kAlphaWelsch, 1.0}));
  EXPECT_NO_THROW(swslam::graph::checkKernel({2.0, 1.0}));
}
