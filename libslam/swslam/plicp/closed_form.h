#pragma once
// The closed-form minimization of PLICP's point-to-line cost (paper eq. 1-3), after
// Censi 2008: with x = [tx, ty, cos(th), sin(th)], the cost is x'Mx + g'x under the
// constraint x'Wx = 1, W = diag(0, 0, 1, 1). A Lagrange multiplier reduces it to one
// quartic in lambda (eq. 2-3). See doc/plicp.md for the derivation and the paper's typos.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

namespace swslam::plicp
{
/** One residual n'(R p + t - q) of eq. (1). */
struct PointToLine
{
  Eigen::Vector2d p;  ///< current point (current sensor frame)
  Eigen::Vector2d q;  ///< reference point p_j1 (reference sensor frame)
  Eigen::Vector2d n;  ///< unit normal of the reference surface at q
};

/** Cost matrices of eq. (1) written as x'Mx + g'x (+ const). */
void buildCost(const std::vector<PointToLine>& terms, Eigen::Matrix4d& M, Eigen::Vector4d& g);

/** Coefficients [a, b, c, d, e] of a*l^4 + b*l^3 + c*l^2 + d*l + e = 0 (eq. 3), obtained
 * by expanding eq. (2). With M = [A B; B' D], S = D - B'A^-1 B, S^A = det(S) S^-1 and
 * h = g2 - B'A^-1 g1 (our corrected form, see doc/plicp.md):
 *   a = 16, b = 32 tr S, c = 16 tr(S)^2 + 32 |S| - 4 h'h,
 *   d = 32 tr(S)|S| - 8 h'S^A h, e = 16 |S|^2 - 4 h'S^A' S^A h.
 * Requires A invertible. */
std::array<double, 5> quarticCoefficients(const Eigen::Matrix4d& M, const Eigen::Vector4d& g);

/** The coefficients as printed in the paper's eq. (3) (kept to document its typos). */
std::array<double, 5> quarticCoefficientsAsPrinted(const Eigen::Matrix4d& M,
                                                   const Eigen::Vector4d& g);

/** Left-hand side of eq. (2) minus 1, evaluated directly (for tests). */
double lagrangeConstraintResidual(const Eigen::Matrix4d& M, const Eigen::Vector4d& g,
                                  double lambda);

/** Real roots of a quartic [a..e] (a != 0), each polished by Newton steps. */
std::vector<double> quarticRealRoots(const std::array<double, 5>& coeffs);

/** Minimizes x'Mx + g'x with cos^2 + sin^2 = 1 exactly. The global minimum is the one root
 * of the Lagrange condition with S + lambda I positive semi-definite: it is found by Newton
 * on the 2x2 secular equation (no quartic to solve). If that gives nothing usable, every
 * real root of the quartic is tried (minimizeOnCircleByQuartic()), and if none is usable
 * (degenerate cost) a dense search over the angle with Newton refinement. Returns
 * [tx, ty, theta], or nothing if M is not finite. `M` must have an invertible block A. */
std::optional<Eigen::Vector3d> minimizeOnCircle(const Eigen::Matrix4d& M, const Eigen::Vector4d& g);

/** The same minimum from the roots of the quartic of eq. (3), each tried and the one of
 * least cost kept (then the angle search if none is usable). Slower; kept as the paper's
 * method and to check minimizeOnCircle() against. */
std::optional<Eigen::Vector3d> minimizeOnCircleByQuartic(const Eigen::Matrix4d& M,
                                                         const Eigen::Vector4d& g);

/** Solves eq. (1) for the terms. A tiny Tikhonov pull towards `anchor` ([tx, ty, th], the
 * current estimate) keeps directions the scene does not constrain (a corridor's axis)
 * where they are instead of letting them float on round-off. */
std::optional<Eigen::Vector3d> solvePointToLine(const std::vector<PointToLine>& terms,
                                                const Eigen::Vector3d& anchor);

}  // namespace swslam::plicp
