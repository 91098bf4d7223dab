#include <swslam/eval/se2_alignment.h>

#include <mrpt/math/wrap2pi.h>

#include <gtest/gtest.h>

#include <random>

using swslam::eval::alignmentCost;
using swslam::eval::alignSE2;

namespace
{
std::vector<Eigen::Vector2d> randomPoints(size_t n, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-20, 20);
  std::vector<Eigen::Vector2d> p;
  for (size_t i = 0; i < n; i++) p.emplace_back(u(rng), u(rng));
  return p;
}

std::vector<Eigen::Vector2d> apply(const mrpt::poses::CPose2D& T,
                                   const std::vector<Eigen::Vector2d>& a)
{
  std::vector<Eigen::Vector2d> out;
  for (const auto& p : a)
  {
    double x, y;
    T.composePoint(p.x(), p.y(), x, y);
    out.emplace_back(x, y);
  }
  return out;
}

// Numeric minimization with no closed form: a 0.5 deg grid over the angle, then golden-section
// refinement; for each angle the translation is found by a few Gauss-Newton steps from zero
// on the cost itself (linear in t, so they converge, but nothing assumes the centroid formula).
mrpt::poses::CPose2D numericAlign(const std::vector<Eigen::Vector2d>& a,
                                  const std::vector<Eigen::Vector2d>& b)
{
  const auto bestFor = [&](double th) {
    Eigen::Vector2d t = Eigen::Vector2d::Zero();
    for (int it = 0; it < 3; it++)
    {
      Eigen::Vector2d g = Eigen::Vector2d::Zero();  // gradient / (2n): mean residual
      for (size_t i = 0; i < a.size(); i++)
      {
        const Eigen::Vector2d ra(std::cos(th) * a[i].x() - std::sin(th) * a[i].y(),
                                 std::sin(th) * a[i].x() + std::cos(th) * a[i].y());
        g += b[i] - ra - t;
      }
      t += g / a.size();
    }
    return mrpt::poses::CPose2D(t.x(), t.y(), th);
  };
  const auto cost = [&](double th) { return alignmentCost(bestFor(th), a, b); };
  double best = -M_PI;
  for (double th = -M_PI; th < M_PI; th += M_PI / 360)
    if (cost(th) < cost(best)) best = th;
  double lo = best - M_PI / 360, hi = best + M_PI / 360;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 100; it++)
  {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (cost(m1) < cost(m2))
      hi = m2;
    else
      lo = m1;
  }
  return bestFor(0.5 * (lo + hi));
}
}  // namespace

TEST(EvalSe2Alignment, RecoversAnExactRigidTransform)
{
  std::mt19937 rng(1);
  for (const double yaw : {0.0, 0.7, -2.5, M_PI - 1e-3, 3.0})
  {
    const mrpt::poses::CPose2D T(12.5, -3.25, yaw);
    const auto a = randomPoints(30, rng);
    const auto found = alignSE2(a, apply(T, a));
    EXPECT_NEAR(found.x(), T.x(), 1e-9);
    EXPECT_NEAR(found.y(), T.y(), 1e-9);
    EXPECT_NEAR(mrpt::math::wrapToPi(found.phi() - yaw), 0, 1e-12);
    EXPECT_NEAR(alignmentCost(found, a, apply(T, a)), 0, 1e-16);
  }
}

TEST(EvalSe2Alignment, EqualsNumericMinimizationOnNoisyPoints)
{
  std::mt19937 rng(2);
  std::normal_distribution<double> noise(0, 1.5);
  for (int trial = 0; trial < 10; trial++)
  {
    const mrpt::poses::CPose2D T(noise(rng) * 5, noise(rng) * 5, 1.1 * trial - 5);
    const auto a = randomPoints(8 + trial, rng);
    auto b = apply(T, a);
    for (auto& p : b) p += Eigen::Vector2d(noise(rng), noise(rng));
    const auto closed = alignSE2(a, b);
    const auto numeric = numericAlign(a, b);
    EXPECT_NEAR(closed.x(), numeric.x(), 1e-6);
    EXPECT_NEAR(closed.y(), numeric.y(), 1e-6);
    EXPECT_NEAR(mrpt::math::wrapToPi(closed.phi() - numeric.phi()), 0, 1e-7);
    EXPECT_LE(alignmentCost(closed, a, b), alignmentCost(numeric, a, b) + 1e-9);
    // And no nearby transform does better.
    for (const auto& d : {mrpt::poses::CPose2D(1e-3, 0, 0), mrpt::poses::CPose2D(0, -1e-3, 0),
                          mrpt::poses::CPose2D(0, 0, 1e-3), mrpt::poses::CPose2D(0, 0, -1e-3)})
      EXPECT_LT(alignmentCost(closed, a, b), alignmentCost(d + closed, a, b));
  }
}

TEST(EvalSe2Alignment, DegenerateAndBadInput)
{
  // A single point: the translation is exact, the rotation undetermined (0).
  const auto one = alignSE2({{1, 2}}, {{4, 6}});
  EXPECT_NEAR(alignmentCost(one, {{1, 2}}, {{4, 6}}), 0, 1e-18);
  EXPECT_THROW(alignSE2({}, {}), std::invalid_argument);
  EXPECT_THROW(alignSE2({{0, 0}}, {{0, 0}, {1, 1}}), std::invalid_argument);
}
