#include <swslam/graph/normal_equations.h>

#include <swslam/graph/block_amd_ordering.h>

#include <algorithm>
#include <cmath>

namespace swslam::graph
{
double NormalEquations::fillPerColumnOf(int free_blocks, const std::vector<std::pair<int, int>>& pairs)
{
  std::vector<std::pair<int, int>> free_pairs;
  free_pairs.reserve(pairs.size());
  for (const auto& ab : pairs)
    if (ab.first >= 0 && ab.second >= 0) free_pairs.push_back(ab);
  return NormalEquations(free_blocks, free_pairs, false).fillPerColumn();
}

NormalEquations::NormalEquations(int free_blocks, const std::vector<std::pair<int, int>>& pairs, bool dense_solver)
    : position_(amdBlockOrder(free_blocks, pairs)),  // checks the pairs
      H_(3 * free_blocks, 3 * free_blocks),
      g_(Eigen::VectorXd::Zero(3 * free_blocks)),
      rhs_(3 * free_blocks)
{
  // The upper triangle's pattern, in stored block order, written straight into compressed
  // storage: per block column B, full blocks at the rows of its coupled blocks A < B in
  // increasing order, then the upper half of the diagonal block.
  std::vector<std::vector<int>> above(static_cast<size_t>(free_blocks));
  for (const auto& [a, b] : pairs)
  {
    if (a == b) continue;
    const int pa = position_[static_cast<size_t>(a)], pb = position_[static_cast<size_t>(b)];
    above[static_cast<size_t>(std::max(pa, pb))].push_back(std::min(pa, pb));
  }
  Eigen::Index nnz = 0;
  for (auto& rows : above)
  {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    nnz += 6 + 9 * static_cast<Eigen::Index>(rows.size());
  }
  H_.resizeNonZeros(nnz);
  int* outer = H_.outerIndexPtr();
  int* inner = H_.innerIndexPtr();
  int s = 0;
  for (int B = 0; B < free_blocks; ++B)
    for (int c = 0; c < 3; ++c)
    {
      outer[3 * B + c] = s;
      for (const int A : above[static_cast<size_t>(B)])
        for (int r = 0; r < 3; ++r) inner[s++] = 3 * A + r;
      for (int r = 0; r <= c; ++r) inner[s++] = 3 * B + r;
    }
  outer[3 * free_blocks] = s;
  std::fill(H_.valuePtr(), H_.valuePtr() + nnz, 0.0);
  diagonal_slots_.resize(g_.size());
  for (int a = 0; a < free_blocks; ++a)
    for (int k = 0; k < 3; ++k)
    {
      const int i = 3 * position_[static_cast<size_t>(a)] + k;
      diagonal_slots_[3 * a + k] = slot(i, i);
    }
  damped_ = H_;
  simplicial_.analyzePattern(damped_);
  fill_per_column_ = simplicial_.factorNonZeros() / std::max<Eigen::Index>(1, g_.size());
  if (dense_solver && g_.size() >= kCholmodMinDimension && fill_per_column_ > kCholmodMinFillPerColumn)
  {
    // A dense factor (an area revisited over and over): CHOLMOD's supernodal Cholesky.
    use_cholmod_ = true;
    // Nested dissection (METIS) rather than CHOLMOD's default minimum degree: on the
    // 3500-node grid of the false-loop benchmark a third fewer flops per factorization
    // (5.1e7 against 7.2e7; with 1000 false loops 1.9e9 against 3.0e9), for about 40 ms more
    // analysis. Without METIS, CHOLMOD's own choice.
    cholmod_.cholmod().nmethods = 1;
    cholmod_.cholmod().method[0].ordering = CHOLMOD_METIS;
    cholmod_.analyzePattern(damped_);
    if (cholmod_.cholmod().status != CHOLMOD_OK)
    {
      cholmod_.cholmod().nmethods = 0;
      cholmod_.cholmod().status = CHOLMOD_OK;
      cholmod_.analyzePattern(damped_);
    }
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
  off_pattern_.clear();
}

void NormalEquations::addOffPattern(int a, int b, const Eigen::Matrix3d& block)
{
  off_pattern_.push_back({position_.at(static_cast<size_t>(a)), position_.at(static_cast<size_t>(b)), block});
}

Eigen::VectorXd NormalEquations::dampedProduct(const Eigen::VectorXd& x) const
{
  Eigen::VectorXd y = damped_.selfadjointView<Eigen::Upper>() * x;
  for (const auto& o : off_pattern_)
  {
    y.segment<3>(3 * o.row) += o.block * x.segment<3>(3 * o.col);
    y.segment<3>(3 * o.col) += o.block.transpose() * x.segment<3>(3 * o.row);
  }
  return y;
}

bool NormalEquations::factorSolve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
{
  if (use_cholmod_)
  {
    x = cholmod_.solve(b);
    return cholmod_.info() == Eigen::Success;
  }
  x = simplicial_.solve(b);
  return simplicial_.info() == Eigen::Success;
}

void NormalEquations::addStoredBlock(int row_block, int col_block, const Eigen::Matrix3d& block)
{
  // The three columns of a block column hold the same rows above the diagonal block, so a
  // block's rows sit at the same offset from each column's start: one search finds all
  // three. A diagonal block keeps its upper half, the last entries of each column.
  double* values = H_.valuePtr();
  const int* outer = H_.outerIndexPtr();
  const int first_col = 3 * col_block;
  if (row_block == col_block)
  {
    for (int c = 0; c < 3; ++c)
    {
      int s = outer[first_col + c + 1] - (c + 1);
      for (int r = 0; r <= c; ++r) values[s++] += block(r, c);
    }
    return;
  }
  const int offset = slot(3 * row_block, first_col) - outer[first_col];
  for (int c = 0; c < 3; ++c)
  {
    int s = outer[first_col + c] + offset;
    for (int r = 0; r < 3; ++r) values[s++] += block(r, c);
  }
}

void NormalEquations::addDiagonal(int a, const Eigen::Matrix3d& block)
{
  const int p = position_[static_cast<size_t>(a)];
  addStoredBlock(p, p, block);
}

void NormalEquations::addOffDiagonal(int a, int b, const Eigen::Matrix3d& block)
{
  const int pa = position_[static_cast<size_t>(a)], pb = position_[static_cast<size_t>(b)];
  if (pa < pb) addStoredBlock(pa, pb, block);
  else addStoredBlock(pb, pa, block.transpose());
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
  const int blocks = static_cast<int>(position_.size());
  for (int a = 0; a < blocks; ++a) rhs_.segment<3>(3 * position_[a]) = -g_.segment<3>(3 * a);
  Eigen::VectorXd stored;
  if (use_cholmod_)
  {
    cholmod_.factorize(damped_);
    if (cholmod_.info() != Eigen::Success) return false;
  }
  else
  {
    simplicial_.factorize(damped_);
    if (simplicial_.info() != Eigen::Success) return false;
  }
  if (!factorSolve(rhs_, stored)) return false;
  refine_iterations_ = 0;
  if (!off_pattern_.empty())
  {
    // Preconditioned conjugate gradients from the pattern's solution; the damped system is
    // positive definite (each edge's term is, and so is the damping).
    Eigen::VectorXd r = rhs_ - dampedProduct(stored), z, p, q;
    const double target = kRefineTolerance * rhs_.norm();
    if (!factorSolve(r, z)) return false;
    p = z;
    double rz = r.dot(z);
    while (r.norm() > target && refine_iterations_ < kMaxRefineIterations && rz > 0)
    {
      ++refine_iterations_;
      q = dampedProduct(p);
      const double pq = p.dot(q);
      if (!(pq > 0)) break;
      const double step = rz / pq;
      stored += step * p;
      r -= step * q;
      if (!factorSolve(r, z)) return false;
      const double rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
  }
  dx.resize(g_.size());
  for (int a = 0; a < blocks; ++a) dx.segment<3>(3 * a) = stored.segment<3>(3 * position_[a]);
  return dx.allFinite();
}

double NormalEquations::predictedDecrease(double lambda, const Eigen::VectorXd& dx) const
{
  double s = -dx.dot(g_);
  for (int i = 0; i < g_.size(); ++i)
    s += lambda * std::max(H_.valuePtr()[diagonal_slots_[i]], 1e-12) * dx[i] * dx[i];
  return 0.5 * s;
}

}  // namespace swslam::graph
