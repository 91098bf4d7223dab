#include "swslam/normal_equations.h"

#include <algorithm>
#include <cmath>

namespace swslam
{
NormalEquations::NormalEquations(int free_blocks, const std::vector<std::pair<int, int>>& pairs)
    : H_(3 * free_blocks, 3 * free_blocks),
      g_(Eigen::VectorXd::Zero(3 * free_blocks))
{
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(6 * free_blocks + 9 * pairs.size());
  for (int a = 0; a < free_blocks; ++a)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c <= r; ++c) pattern.emplace_back(3 * a + r, 3 * a + c, 0.0);
  for (const auto& [a, b] : pairs)
  {
    const int hi = std::max(a, b), lo = std::min(a, b);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) pattern.emplace_back(3 * hi + r, 3 * lo + c, 0.0);
  }
  H_.setFromTriplets(pattern.begin(), pattern.end());
  H_.makeCompressed();
  diagonal_slots_.resize(g_.size());
  for (int i = 0; i < g_.size(); ++i) diagonal_slots_[i] = slot(i, i);
  damped_ = H_;
  simplicial_.analyzePattern(damped_);
  const double fill = simplicial_.factorNonZeros() / std::max<Eigen::Index>(1, g_.size());
  if (g_.size() >= kCholmodMinDimension && fill > kCholmodMinFillPerColumn)
  {
    // A dense factor (an area revisited over and over): CHOLMOD's supernodal Cholesky.
    use_cholmod_ = true;
    cholmod_.analyzePattern(damped_);
  }
}

int NormalEquations::slot(int row, int col) const
{
  const int* begin = H_.innerIndexPtr() + H_.outerIndexPtr()[col];
  const int* end = H_.innerIndexPtr() + H_.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - H_.innerIndexPtr());
}

void NormalEquations::setZero()
{
  std::fill(H_.valuePtr(), H_.valuePtr() + H_.nonZeros(), 0.0);
  g_.setZero();
}

void NormalEquations::addBlock(int row_block, int col_block, const Eigen::Matrix3d& block)
{
  // Within a column the three rows of a block are contiguous in the compressed storage.
  double* values = H_.valuePtr();
  for (int c = 0; c < 3; ++c)
  {
    const int col = 3 * col_block + c;
    const int first_row = row_block == col_block ? col : 3 * row_block;
    int s = slot(first_row, col);
    for (int r = first_row - 3 * row_block; r < 3; ++r) values[s++] += block(r, c);
  }
}

void NormalEquations::addDiagonal(int a, const Eigen::Matrix3d& block) { addBlock(a, a, block); }

void NormalEquations::addOffDiagonal(int a, int b, const Eigen::Matrix3d& block)
{
  if (a > b) addBlock(a, b, block);
  else addBlock(b, a, block.transpose());
}

bool NormalEquations::solveDamped(double lambda, Eigen::VectorXd& dx)
{
  std::copy(H_.valuePtr(), H_.valuePtr() + H_.nonZeros(), damped_.valuePtr());
  for (int i = 0; i < g_.size(); ++i)
  {
    // Marquardt scaling, floored so that a zero-curvature direction is still damped.
    const double d = std::max(H_.valuePtr()[diagonal_slots_[i]], 1e-12);
    damped_.valuePtr()[diagonal_slots_[i]] += lambda * d;
  }
  if (use_cholmod_)
  {
    cholmod_.factorize(damped_);
    if (cholmod_.info() != Eigen::Success) return false;
    dx = cholmod_.solve(-g_);
    return cholmod_.info() == Eigen::Success && dx.allFinite();
  }
  simplicial_.factorize(damped_);
  if (simplicial_.info() != Eigen::Success) return false;
  dx = simplicial_.solve(-g_);
  return simplicial_.info() == Eigen::Success && dx.allFinite();
}

double NormalEquations::predictedDecrease(double lambda, const Eigen::VectorXd& dx) const
{
  double s = -dx.dot(g_);
  for (int i = 0; i < g_.size(); ++i)
    s += lambda * std::max(H_.valuePtr()[diagonal_slots_[i]], 1e-12) * dx[i] * dx[i];
  return 0.5 * s;
}

}  // namespace swslam
