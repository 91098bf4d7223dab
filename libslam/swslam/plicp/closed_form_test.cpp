// The closed-form PLICP step (paper eq. 1-3) against numeric and brute-force versions.
#include <swslam/plicp/closed_form.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace swslam::plicp;

namespace
{
/** Random point-to-line terms generated from a true pose, with some noise. */
std::vector<PointToLine> randomTerms(std::mt19937& rng, const Eigen::Vector3d& truth, int n,
                                     double noise)
{
  std::uniform_real_distribution<double> U(-10, 10), A(-M_PI, M_PI);
  std::normal_distribution<double> N(0, noise);
  std::vector<PointToLine> terms;
  const Eigen::Rotation2Dd R(truth.z());
  for (int k = 0; k < n; k++)
  {
    const Eigen::Vector2d p(U(rng), U(rng));
    const double a = A(rng);
    const Eigen::Vector2d nrm(std::cos(a), std::sin(a));
    // q lies on the line through R p + t with normal nrm, offset by noise along the normal.
    const Eigen::Vector2d tangent(-nrm.y(), nrm.x());
    const Eigen::Vector2d q = R * p + truth.head<2>() + U(rng) * 0.1 * tangent + N(rng) * nrm;
    terms.push_back({p, q, nrm});
  }
  return terms;
}

double cost(const std::vector<PointToLine>& terms, const Eigen::Vector3d& x)
{
  const Eigen::Rotation2Dd R(x.z());
  double c = 0;
  for (const auto& t : terms)
  {
    const double r = t.n.dot(R * t.p + x.head<2>() - t.q);
    c += r * r;
  }
  return c;
}

/** Samples the left side of eq. (2), clears its denominator det(2M + 2 lambda W)^2 and fits
 * the quartic through the samples: the coefficients of eq. (3) obtained numerically. */
Eigen::Matrix<double, 5, 1> numericQuartic(const Eigen::Matrix4d& M, const Eigen::Vector4d& g)
{
  constexpr int kSamples = 11;
  Eigen::Matrix<double, kSamples, 5> V;
  Eigen::Matrix<double, kSamples, 1> y;
  const double detA = M.topLeftCorner<2, 2>().determinant();
  const double scale = M.trace();
  for (int k = 0; k < kSamples; k++)
  {
    const double lambda = scale * (-1.0 + 0.2 * k) + 1e-3;
    Eigen::Matrix4d W = Eigen::Matrix4d::Zero();
    W(2, 2) = W(3, 3) = 1;
    const double detK = (2 * M + 2 * lambda * W).determinant();
    // det(2M + 2 lambda W) = 16 det(A) det(S + lambda I): y = -16 det(S + lambda I)^2 * residual.
    const double detQ = detK / (16 * detA);
    y(k) = -16 * detQ * detQ * lagrangeConstraintResidual(M, g, lambda);
    for (int p = 0; p < 5; p++) V(k, p) = std::pow(lambda, 4 - p);
  }
  return V.colPivHouseholderQr().solve(y);
}
}  // namespace

TEST(PlicpClosedForm, QuarticCoefficientsMatchNumericExpansionOfEq2)
{
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; trial++)
  {
    const Eigen::Vector3d truth(0.3 * trial - 2, 1 - 0.1 * trial, 0.15 * trial - 1.2);
    const auto terms = randomTerms(rng, truth, 30, 0.05);
    Eigen::Matrix4d M;
    Eigen::Vector4d g;
    buildCost(terms, M, g);
    const auto closed = quarticCoefficients(M, g);
    const auto numeric = numericQuartic(M, g);
    for (int p = 0; p < 5; p++)
      EXPECT_NEAR(closed[p], numeric(p), 1e-6 * (1 + std::abs(numeric(p))))
          << "coefficient " << p << " trial " << trial;
  }
}

TEST(PlicpClosedForm, CoefficientsAsPrintedInThePaperDoNotSolveEq2)
{
  // Documents the typo (doc/plicp.md): the printed b..e differ from the expansion of eq. (2).
  std::mt19937 rng(3);
  const auto terms = randomTerms(rng, {1, 2, 0.5}, 30, 0.05);
  Eigen::Matrix4d M;
  Eigen::Vector4d g;
  buildCost(terms, M, g);
  const auto printed = quarticCoefficientsAsPrinted(M, g);
  const auto numeric = numericQuartic(M, g);
  EXPECT_GT(std::abs(printed[1] - numeric(1)), 1e-3 * std::abs(numeric(1)));
}

TEST(PlicpClosedForm, RootsOfTheQuarticSatisfyEq2)
{
  std::mt19937 rng(11);
  const auto terms = randomTerms(rng, {-1, 0.5, 2.0}, 40, 0.02);
  Eigen::Matrix4d M;
  Eigen::Vector4d g;
  buildCost(terms, M, g);
  const auto roots = quarticRealRoots(quarticCoefficients(M, g));
  ASSERT_FALSE(roots.empty());
  for (double l : roots) EXPECT_NEAR(lagrangeConstraintResidual(M, g, l), 0, 1e-6);
}

TEST(PlicpClosedForm, MinimizerEqualsBruteForceOverTheAngle)
{
  std::mt19937 rng(5);
  for (int trial = 0; trial < 50; trial++)
  {
    const Eigen::Vector3d truth(0.4 * trial - 10, 3 - 0.2 * trial, -3.0 + 0.12 * trial);
    const auto terms = randomTerms(rng, truth, 25, trial % 2 ? 0.3 : 0.01);
    const auto x = solvePointToLine(terms, Eigen::Vector3d::Zero());
    ASSERT_TRUE(x.has_value());
    // Brute force: fine angle grid, translation by linear least squares at each angle.
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 36000; k++)
    {
      const double th = -M_PI + 2 * M_PI * k / 36000;
      const Eigen::Rotation2Dd R(th);
      Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
      Eigen::Vector2d b = Eigen::Vector2d::Zero();
      for (const auto& t : terms)
      {
        A += t.n * t.n.transpose();
        b -= t.n * t.n.dot(R * t.p - t.q);
      }
      const Eigen::Vector2d t = A.inverse() * b;
      best = std::min(best, cost(terms, {t.x(), t.y(), th}));
    }
    EXPECT_LE(cost(terms, *x), best + 1e-9) << "trial " << trial;
  }
}

TEST(PlicpClosedForm, ExactDataRecoversThePose)
{
  std::mt19937 rng(9);
  for (double th : {-3.1, -1.0, 0.0, 0.7, 3.1})
  {
    const Eigen::Vector3d truth(2.5, -1.5, th);
    const auto x = solvePointToLine(randomTerms(rng, truth, 20, 0.0), Eigen::Vector3d::Zero());
    ASSERT_TRUE(x.has_value());
    EXPECT_NEAR(x->x(), truth.x(), 1e-6);
    EXPECT_NEAR(x->y(), truth.y(), 1e-6);
    EXPECT_NEAR(std::remainder(x->z() - th, 2 * M_PI), 0, 1e-7);
  }
}

TEST(PlicpClosedForm, DegenerateCorridorKeepsTheUnconstrainedAxisAtTheAnchor)
{
  // Every normal along y: x is unobservable and must stay where the anchor puts it.
  std::vector<PointToLine> terms;
  for (int k = 0; k < 40; k++)
  {
    const double px = -10 + 0.5 * k, side = k % 2 ? 1.0 : -1.0;
    terms.push_back({{px, side}, {px + 0.3, side + 0.2}, {0, 1}});
  }
  const auto x = solvePointToLine(terms, Eigen::Vector3d(0.7, 0, 0));
  ASSERT_TRUE(x.has_value());
  EXPECT_TRUE(x->allFinite());
  EXPECT_NEAR(x->y(), 0.2, 1e-6);
  EXPECT_NEAR(x->z(), 0.0, 1e-6);
  EXPECT_NEAR(x->x(), 0.7, 1e-3);
}

TEST(PlicpClosedForm, SecularEquationAgreesWithTheQuarticRoots)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  int compared = 0;
  for (int trial = 0; trial < 400; trial++)
  {
    Eigen::Matrix4d M;
    Eigen::Vector4d g;
    if (trial % 2 == 0)
    {
      const Eigen::Vector3d truth(5 * U(rng), 5 * U(rng), M_PI * U(rng));
      buildCost(randomTerms(rng, truth, 4 + trial % 30, trial % 4 ? 0.5 : 0.001), M, g);
    }
    else  // random positive definite M and g, some with near-degenerate rotation blocks
    {
      Eigen::Matrix4d L = Eigen::Matrix4d::Random();
      M = L * L.transpose() + 1e-3 * Eigen::Matrix4d::Identity();
      if (trial % 6 == 1) M.bottomRightCorner<2, 2>() += 1e3 * Eigen::Matrix2d::Identity();
      g = Eigen::Vector4d::Random() * (trial % 10 == 3 ? 1e-6 : 3.0);
    }
    const auto a = minimizeOnCircle(M, g), b = minimizeOnCircleByQuartic(M, g);
    ASSERT_TRUE(a && b);
    auto f = [&](const Eigen::Vector3d& x) {
      const Eigen::Vector4d v(x.x(), x.y(), std::cos(x.z()), std::sin(x.z()));
      return v.dot(M * v) + g.dot(v);
    };
    // Same minimum value (the minimizer itself may differ on exact ties).
    EXPECT_LE(f(*a), f(*b) + 1e-9 * (1 + std::abs(f(*b)))) << "trial " << trial;
    compared++;
  }
  EXPECT_EQ(compared, 400);
}

TEST(PlicpClosedForm, SecularEquationHandlesTheHardCase)
{
  // h = 0: u'Su on the unit circle is least along S's smallest eigenvector.
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  M(2, 2) = 3;
  M(3, 3) = 1;
  const auto x = minimizeOnCircle(M, Eigen::Vector4d::Zero());
  ASSERT_TRUE(x);
  EXPECT_NEAR(std::abs(std::sin(x->z())), 1.0, 1e-9);
}
