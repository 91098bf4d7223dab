#pragma once
// Sparse normal equations H dx = -g of a pose graph, stored in 3x3 blocks: the pattern is
// built once per problem, then each linearization only adds into fixed value slots, and
// each damped solve reuses the symbolic factorization. The blocks are stored in a
// fill-reducing order (AMD on the graph of the blocks, block_amd_ordering.h), so that the
// factorization works on H as stored, with no permuted copy per solve. Eigen's simplicial
// LDL^T is used while its factor stays sparse, as along a trajectory with few loops; when
// the factor is dense (an area revisited over and over), CHOLMOD's supernodal Cholesky
// takes over, measurably faster there, with a nested-dissection (METIS) ordering
// (doc/graph-optimization.md).

#include <Eigen/Core>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <utility>
#include <vector>

namespace swslam::graph
{
class NormalEquations
{
 public:
  /** `free_blocks` variables of 3 dofs each; `pairs` lists the (a, b) block pairs, a != b,
   * that edges couple (duplicates and either order allowed; a == b adds nothing). Edges
   * touching one free variable only need the diagonal block, always present. Throws
   * std::invalid_argument for a block index outside [0, free_blocks). */
  NormalEquations(int free_blocks, const std::vector<std::pair<int, int>>& pairs)
      : NormalEquations(free_blocks, pairs, true)
  {
  }

  void setZero();
  /** H_aa += block (a symmetric block). */
  void addDiagonal(int a, const Eigen::Matrix3d& block);
  /** H_ab += block (and H_ba += block^T implicitly: one triangle is stored). */
  void addOffDiagonal(int a, int b, const Eigen::Matrix3d& block);
  /** H_ab += block for a pair (a != b) outside the pattern: kept aside, so that the solve
   * is still exact, by conjugate gradients preconditioned with the factor of the pattern's
   * part (coupled_system.h). */
  void addOffPattern(int a, int b, const Eigen::Matrix3d& block);
  /** g, in the variables' own order (as dx). */
  Eigen::VectorXd& gradient() { return g_; }

  /** Solves (H + lambda diag(H)) dx = -g. Returns false if the factorization fails. With
   * blocks off the pattern, the solve of the pattern's part is refined by preconditioned
   * conjugate gradients to a relative residual of kRefineTolerance (at most
   * kMaxRefineIterations). */
  bool solveDamped(double lambda, Eigen::VectorXd& dx);
  /** Conjugate-gradient iterations of the last solveDamped (0 without off-pattern blocks). */
  int refineIterations() const { return refine_iterations_; }
  static constexpr double kRefineTolerance = 1e-8;
  static constexpr int kMaxRefineIterations = 200;
  /** dx^T (lambda diag(H) dx - g) / 2: the decrease the damped model predicts. */
  double predictedDecrease(double lambda, const Eigen::VectorXd& dx) const;

  int dimension() const { return static_cast<int>(g_.size()); }
  /** True if the supernodal CHOLMOD factorization is used. */
  bool usesCholmod() const { return use_cholmod_; }
  /** Non-zeros per column of the factor in the blocks' AMD order (the symbolic analysis). */
  double fillPerColumn() const { return fill_per_column_; }
  /** fillPerColumn() of the normal equations of these pairs (a pair with a block -1, a fixed
   * pose, adds nothing), from the blocks' AMD order and the simplicial analysis alone (no
   * CHOLMOD analysis however dense). */
  static double fillPerColumnOf(int free_blocks, const std::vector<std::pair<int, int>>& pairs);

  /** CHOLMOD is used for systems of at least this many unknowns whose factor holds more
   * than kCholmodMinFillPerColumn non-zeros per column (decided by the symbolic analysis). */
  static constexpr int kCholmodMinDimension = 300;
  static constexpr double kCholmodMinFillPerColumn = 120.0;

 private:
  /** With `dense_solver` false, the simplicial factorization whatever the fill (for
   * fillPerColumnOf(), which solves nothing). */
  NormalEquations(int free_blocks, const std::vector<std::pair<int, int>>& pairs, bool dense_solver);
  int slot(int row, int col) const;  // index into H_.valuePtr() of (row, col), row <= col
  /** H_{row_block, col_block} += block, in stored (ordered) block indices, row <= col. */
  void addStoredBlock(int row_block, int col_block, const Eigen::Matrix3d& block);

  std::vector<int> position_;        // per variable block, its block in H_ (AMD order)
  Eigen::SparseMatrix<double> H_;    // upper triangle incl. the diagonal blocks', ordered
  Eigen::SparseMatrix<double> damped_;
  std::vector<int> diagonal_slots_;  // per scalar variable (own order), slot of its H(i, i)
  Eigen::VectorXd g_;                // own order
  Eigen::VectorXd rhs_;              // -g in stored order
  /** Simplicial LDL^T on H as stored, that tells the size of its factor right after the
   * symbolic analysis. */
  struct SimplicialSolver
      : Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>>
  {
    double factorNonZeros() const { return m_nonZerosPerCol.cast<double>().sum(); }
  };

  /** (H + lambda diag(H)) x in stored order, off-pattern blocks included. */
  Eigen::VectorXd dampedProduct(const Eigen::VectorXd& x) const;
  /** The factor's solve, in stored order. */
  bool factorSolve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  struct OffPatternBlock
  {
    int row, col;  // stored block indices
    Eigen::Matrix3d block;
  };
  std::vector<OffPatternBlock> off_pattern_;
  int refine_iterations_ = 0;
  double fill_per_column_ = 0;

  bool use_cholmod_ = false;
  SimplicialSolver simplicial_;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Upper> cholmod_;
};

}  // namespace swslam::graph
