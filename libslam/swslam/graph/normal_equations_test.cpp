// The block-sparse normal equations against a dense solve of the same damped system, on
// both factorization paths (simplicial LDL^T for a sparse factor, CHOLMOD for a dense one).
#include <swslam/graph/normal_equations.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>

namespace
{
/** Fills the system with random blocks at `pairs` (the pattern given by `pattern_pairs`,
 * by default the same), and at `off_pattern` outside the pattern, and solves it. */
void checkAgainstDense(int blocks, const std::vector<std::pair<int, int>>& pairs, bool cholmod,
                       const std::vector<std::pair<int, int>>* pattern_pairs = nullptr,
                       const std::vector<std::pair<int, int>>& off_pattern = {})
{
  std::mt19937 rng(9);
  std::normal_distribution<double> n01;
  swslam::graph::NormalEquations ne(blocks, pattern_pairs ? *pattern_pairs : pairs);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * blocks, 3 * blocks);
  auto randomBlock = [&] {
    Eigen::Matrix3d b;
    for (int k = 0; k < 9; ++k) b(k / 3, k % 3) = n01(rng);
    return b;
  };
  for (int a = 0; a < blocks; ++a)
  {
    const Eigen::Matrix3d m = randomBlock();
    const Eigen::Matrix3d spd = m * m.transpose() + 50 * Eigen::Matrix3d::Identity();
    ne.addDiagonal(a, spd);
    dense.block<3, 3>(3 * a, 3 * a) += spd;
  }
  for (const auto& [a, b] : pairs)
  {
    const Eigen::Matrix3d m = 0.3 * randomBlock();
    ne.addOffDiagonal(a, b, m);  // H_ab += m, H_ba += m^T
    dense.block<3, 3>(3 * a, 3 * b) += m;
    dense.block<3, 3>(3 * b, 3 * a) += m.transpose();
  }
  for (const auto& [a, b] : off_pattern)
  {
    const Eigen::Matrix3d m = 0.3 * randomBlock();
    ne.addOffPattern(a, b, m);
    dense.block<3, 3>(3 * a, 3 * b) += m;
    dense.block<3, 3>(3 * b, 3 * a) += m.transpose();
  }
  for (int i = 0; i < 3 * blocks; ++i) ne.gradient()[i] = n01(rng);
  const double lambda = 0.01;
  Eigen::VectorXd dx;
  ASSERT_TRUE(ne.solveDamped(lambda, dx));
  EXPECT_EQ(ne.usesCholmod(), cholmod);
  if (off_pattern.empty())
  {
    EXPECT_EQ(ne.refineIterations(), 0);
  }
  else  // refined, and to the tolerance before the iterations ran out
  {
    EXPECT_GT(ne.refineIterations(), 0);
    EXPECT_LT(ne.refineIterations(), swslam::graph::NormalEquations::kMaxRefineIterations);
  }
  Eigen::MatrixXd damped = dense;
  damped.diagonal() += lambda * dense.diagonal();
  const Eigen::VectorXd expected = damped.ldlt().solve(-ne.gradient());
  EXPECT_LT((dx - expected).norm(), 1e-9 * expected.norm());
  const double predicted = 0.5 * dx.dot(lambda * dense.diagonal().cwiseProduct(dx) - ne.gradient());
  EXPECT_NEAR(ne.predictedDecrease(lambda, dx), predicted, 1e-9 * std::abs(predicted));
}
}  // namespace

TEST(NormalEquations, ChainMatchesDenseSolveWithTheSimplicialFactorization)
{
  std::vector<std::pair<int, int>> pairs;
  for (int a = 1; a < 200; ++a) pairs.emplace_back(a - 1, a), pairs.emplace_back(a, a - 1);
  pairs.emplace_back(0, 199);  // a loop
  checkAgainstDense(200, pairs, false);
}

TEST(NormalEquations, DenselyCoupledSystemSwitchesToCholmod)
{
  std::vector<std::pair<int, int>> pairs;
  for (int a = 0; a < 160; ++a)
    for (int b = 0; b < a; b += 2) pairs.emplace_back(a, b);
  checkAgainstDense(160, pairs, true);
}

TEST(NormalEquations, BlocksOffThePatternAreSolvedExactlyOnBothFactorizations)
{
  // Long edges left out of a chain's pattern (the factor stays tridiagonal) and out of a
  // dense one: conjugate gradients bring their blocks back into the solve.
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> block(0, 199);
  std::vector<std::pair<int, int>> chain, off;
  for (int a = 1; a < 200; ++a) chain.emplace_back(a - 1, a);
  while (off.size() < 40)
  {
    const int a = block(rng), b = block(rng);
    if (std::abs(a - b) > 1) off.emplace_back(a, b);
  }
  checkAgainstDense(200, chain, false, nullptr, off);
  std::vector<std::pair<int, int>> dense;
  for (int a = 0; a < 160; ++a)
    for (int b = 0; b < a; b += 2) dense.emplace_back(a, b);
  std::vector<std::pair<int, int>> odd;  // pairs the dense pattern lacks
  for (int a = 1; a < 160; a += 2) odd.emplace_back(a, a - 1);
  checkAgainstDense(160, dense, true, nullptr, odd);
}

TEST(NormalEquations, SetZeroClearsEverything)
{
  swslam::graph::NormalEquations ne(2, {{0, 1}});
  ne.addDiagonal(0, Eigen::Matrix3d::Identity());
  ne.gradient().setOnes();
  ne.setZero();
  Eigen::VectorXd dx;
  EXPECT_FALSE(ne.solveDamped(1.0, dx) && dx.norm() > 0);  // singular or a zero step
}

TEST(NormalEquations, PairsInEitherOrderDuplicatedOrOnTheDiagonalGiveOnePattern)
{
  // The chain above with each pair once, and again with duplicates, reversed pairs and
  // a == b pairs: the same system, solved the same way.
  std::vector<std::pair<int, int>> once, messy;
  for (int a = 1; a < 50; ++a)
  {
    once.emplace_back(a - 1, a);
    messy.emplace_back(a, a - 1);
    messy.emplace_back(a - 1, a);
    messy.emplace_back(a, a);
  }
  checkAgainstDense(50, once, false);
  checkAgainstDense(50, once, false, &messy);
}

TEST(NormalEquations, PairOutsideTheBlocksIsAnError)
{
  EXPECT_THROW(swslam::graph::NormalEquations(3, {{0, 3}}), std::invalid_argument);
  EXPECT_THROW(swslam::graph::NormalEquations(3, {{-1, 1}}), std::invalid_argument);
}

TEST(NormalEquations, FillProbeEqualsTheAnalysisOfTheSameSystem)
{
  std::vector<std::pair<int, int>> chain, dense;
  for (int a = 1; a < 200; ++a) chain.emplace_back(a - 1, a);
  for (int a = 0; a < 160; ++a)
    for (int b = 0; b < a; b += 2) dense.emplace_back(a, b);
  const swslam::graph::NormalEquations sparse_ne(200, chain), dense_ne(160, dense);
  EXPECT_FALSE(sparse_ne.usesCholmod());
  EXPECT_TRUE(dense_ne.usesCholmod());
  EXPECT_EQ(swslam::graph::NormalEquations::fillPerColumnOf(200, chain), sparse_ne.fillPerColumn());
  EXPECT_EQ(swslam::graph::NormalEquations::fillPerColumnOf(160, dense), dense_ne.fillPerColumn());
  EXPECT_GT(dense_ne.fillPerColumn(), 10 * sparse_ne.fillPerColumn());
  // An edge to a fixed pose (-1) couples nothing.
  chain.emplace_back(-1, 5);
  EXPECT_EQ(swslam::graph::NormalEquations::fillPerColumnOf(200, chain), sparse_ne.fillPerColumn());
}
