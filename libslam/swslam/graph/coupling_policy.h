#pragma once
// Which edges an optimization couples in its normal equations (coupled_system.h): every edge,
// or all but those an outlier kernel has all but switched off, kept apart so that a thousand
// long false loops do not fill the factor in. Graduated non-convexity picks the policy per
// stage (graduated.h); the Levenberg-Marquardt core applies it (levenberg_marquardt.h).

#include <swslam/graph/coupled_system.h>

#include <functional>
#include <utility>
#include <vector>

namespace swslam::graph
{
/** An edge whose weight is below this is decoupled in the non-convex stages of graduated
 * non-convexity (coupled_system.h). With 0.1 (what the default switched_off_weight calls
 * switched off) the true edges still strained after the convex stage were decoupled too, and
 * 1000 false loops then needed more refits than allowed (0.09 m off the optimum). */
inline constexpr double kDecoupledWeight = 0.01;
/** Edges are decoupled once at least this share of them would be (each time the pattern
 * changes its symbolic analysis is redone): not for a few false loops, which add little
 * fill-in. */
inline constexpr double kMinDecoupledShare = 0.01;

/** An exact solve (Coupling::Exact) decouples edges only if every edge coupled fills the
 * factor in beyond this many non-zeros per column, and then those whose weight is below
 * kPreconditionerWeight. On the false-loop benchmark's grid walk (doc/graph-optimization.md)
 * the factor holds about 40 per column with no false loop, 50 with 100 and 130-210 with
 * 1000; the conjugate gradients took 15-25 iterations per solve at weight 0.01, 70-140 at
 * 0.1 (a factor of half the flops) and about 150 with no false loop, where a decoupled true
 * loop still strained from the odometry guess makes them slow. */
inline constexpr double kDenseFillPerColumn = 100.0;
inline constexpr double kPreconditionerWeight = 0.1;

/** Which edges an optimization couples in its normal equations (coupled_system.h). */
enum class Coupling
{
  All,  ///< every edge
  /** Those the last solve kept coupled (of the same edges), less the edges whose weight is
   * below kDecoupledWeight, checked at the start and after every accepted step. */
  DecoupleWeak,
  /** As DecoupleWeak, but from every edge coupled (after an Exact solve, whose decoupled
   * edges were weak at its own start, before its steps). */
  DecoupleWeakAfresh,
  /** Every edge, unless that factor is dense (kDenseFillPerColumn); then the edges weak at
   * the start (kPreconditionerWeight) are decoupled for the whole solve, but their blocks
   * are still in it, off the factor's pattern (conjugate gradients preconditioned by the
   * factor): the step is the coupled one, at the cost of a sparse factor. */
  Exact,
};

/** How an optimization keeps its normal equations. */
struct SystemUse
{
  CoupledSystem* shared = nullptr;  ///< kept across solves (nullptr: one of its own)
  Coupling coupling = Coupling::All;
  /** The damping, carried from one solve to the next that goes on from its poses (nullptr:
   * lm_initial_lambda). In: the damping to start with, if positive, at most
   * lm_initial_lambda; out: the damping at the end. */
  double* damping = nullptr;
};

/** Per edge, whether its IRLS weight at the solve's current poses is below `weight`
 * (robustified edges only). */
using WeakEdges = std::function<std::vector<char>(double weight)>;

/** At least this many edges of `edges` are decoupled at once, or none (kMinDecoupledShare). */
size_t minDecoupled(size_t edges);

/** Prepares `sys` for a solve of `free_blocks` variables whose edges join `pairs`, as
 * `coupling` says (Coupling's cases), `weak` at the solve's starting poses. */
void prepareCoupling(CoupledSystem& sys, Coupling coupling, int free_blocks,
                     const std::vector<std::pair<int, int>>& pairs, const WeakEdges& weak);

/** After an accepted step: under DecoupleWeak(Afresh), the edges now weak are decoupled. */
void decoupleAfterStep(CoupledSystem& sys, Coupling coupling, size_t edges, const WeakEdges& weak);

}  // namespace swslam::graph
