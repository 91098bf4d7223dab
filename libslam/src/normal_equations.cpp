#include "swslam/normal_equations.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swslam
{
NormalEquations::NormalEquations(int free_blocks, const std::vector<std::pair<int, int>>& pairs)
    : H_(3 * free_blocks, 3 * free_blocks),
      g_(Eigen::VectorXd::Zero(3 * free_blocks))
{
  // The lower triangle's pattern, written straight into compressed storage: per block
  // column a, the lower half of the diagonal block, then full blocks at the rows of its
  // coupled blocks b > a, in increasing order.
  std::vector<std::vector<int>> below(static_cast<size_t>(free_blocks));
  for (const auto& [a, b] : pairs)
  {
    if (a < 0 || b < 0 || a >= free_blocks || b >= free_blocks)
      throw std::invalid_argument("NormalEquations: block pair (" + std::to_string(a) + ", " +
                                  std::to_string(b) + ") outside 0.." +
                                  std::to_string(free_blocks - 1));
    if (a != b) below[static_cast<size_t>(std::min(a, b))].push_back(std::max(a, b));
  }
  Eigen::Index nnz = 0;
  for (auto& rows : below)
  {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    nnz += 6 + 9 * static_cast<Eigen::Index>(rows.size());
  }
  H_.resizeNonZeros(nnz);
  int* outer = H_.outerIndexPtr();
  int* inner = H_.innerIndexPtr();
  int s = 0;
  for (int a = 0; a < free_blocks; ++a)
    for (int c = 0; c < 3; ++c)
    {
      outer[3 * a + c] = s;
      for (int r = c; r < 3; ++r) inner[s++] = 3 * a + r;
      for (const int b : below[static_cast<size_t>(a)])
        for (int r = 0; r < 3; ++r) inner[s++] = 3 * b + r;
    }
  outer[3 * free_blocks] = s;
  std::fill(H_.valuePtr(), H_.valuePtr() + nnz, 0.0);
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
