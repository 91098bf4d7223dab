#include <swslam/graph/outlier_decision.h>

#include <swslam/graph/initialization.h>
#include <swslam/graph/levenberg_marquardt.h>
#include <swslam/graph/loop_support.h>
#include <swslam/graph/normal_equations.h>
#include <swslam/graph/single_flip.h>
#include <swslam/graph/truncated.h>

#include <mrpt/math/distributions.h>
#include <mrpt/system/CTicTac.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace swslam::graph
{
namespace
{
/** Rounds of least squares on the edges within the gate, at most. */
constexpr int kMaxRounds = 5;
/** Robust LAGO also over every loop only if at most this many have no neighbour that supports
 * them: each loop between far nodes fills the factor of its linear solves in (city10000 with
 * 10,688 random false loops: seconds per solve, against milliseconds without them). */
constexpr size_t kMaxUnsupportedForLago = 1000;
/** LAGO's proposals are made only where the factor of its linear systems over the edges used
 * holds at most this many non-zeros per column (lagoAffordable): each solve costs about the
 * poses times its square, and robust LAGO solves dozens of times. The public graphs' sets, false
 * loops included, stay at 7-125; city10000 with 10,688 grouped false loops, whose groups support
 * each other, reached 1283 over its consistent loops and 1983 over every edge (over 15 minutes
 * for one case, then not finished). */
constexpr double kMaxLagoFill = 400.0;
/** The loops are also taken one at a time in the chain's order (orderedInliers) only where they
 * number at most this: each that does not fit the poses so far costs a LAGO and up to two
 * least-squares solves (MIT with 20 false loops: 38 of its 40, 0.5 s; CSAIL's 141 with 13 false:
 * 0.65 s where 0.06 s decided them; Intel with 79 grouped: 163 solves, 21 s). Where loops are
 * many, most have neighbours, and the locally consistent loops decide them. */
constexpr size_t kMaxLoopsForOrder = 100;
/** A loop taken in the chain's order that does not fit is kept only if it lowers the cost by at
 * least this share of its gate's square: a decision of that pass is not revisited, so it is taken
 * only when clear (a false loop a weak chain bends to fit lowers it by a little; MIT with 10 false
 * loops, one kept by 1.8 of 25, and the four true loops after it switched off). The refinement
 * that follows takes back the loops within their gates. */
constexpr double kOrderMargin = 0.5;
/** Loops taken in that order that the pass is run again without, at most (orderedInliers). */
constexpr size_t kMaxRetakes = 3;
/** Taken loops asked, per pass, whether a loop turned away after them would be kept without them. */
constexpr size_t kConflictTests = 2;
/** Switched-off edges within this many times their gate are tried back (optimizeTruncated). On
 * the 3500-node grid with 1000 random false loops, 25 true loops lay within 4 gates (24 within 2)
 * and every false loop beyond. */
constexpr double kNearGates = 4.0;
/** Switched-off edges within this many times their gate are also asked whether least squares
 * would take them in for less than their gate's square (tryNearEdges); each asked costs three
 * solves with the kept edges' factor. */
constexpr double kFlipGates = 10.0;
/** Runs of loops tried without their kept loops, at most. */
constexpr size_t kMaxRunTrials = 10;
/** Rounds of those trials, at most: each from the result the last one left, while it lowers the
 * cost (tryWithoutStrainedRuns). */
constexpr size_t kMaxRunRounds = 3;
/** [poses along the chain] a run's loops' ends within this of a switched-off chain edge are at a
 * break of the chain (loop_support.h's window: the loops of one revisit). */
constexpr int kRunWindow = 10;

GraphProblem subset(const GraphProblem& problem, const std::vector<char>& inliers)
{
  GraphProblem kept = problem;
  kept.edges.clear();
  for (size_t k = 0; k < problem.edges.size(); ++k)
    if (inliers[k] || !problem.edges[k].robust) kept.edges.push_back(problem.edges[k]);
  return kept;
}

GraphOptimizerParams leastSquares(const GraphOptimizerParams& params)
{
  GraphOptimizerParams l2 = params;
  l2.kernel_schedule = KernelSchedule::Fixed;
  l2.kernel_alpha = 2;
  return l2;
}

struct Proposal
{
  std::string name;
  std::vector<char> inliers;
  std::vector<geometry::Pose2> start;
};

/** GNC for TLS from the guess: each round a few LM iterations on the edges' information times
 * their weight. */
std::vector<char> guessInliers(const GraphProblem& problem, const OutlierGates& gates, const GraphOptimizerParams& params)
{
  const size_t m = problem.edges.size();
  GraphOptimizerParams step = leastSquares(params);
  step.max_iterations = std::min<size_t>(params.max_iterations, params.gnc_stage_iterations);
  GraphProblem at = problem;
  std::vector<char> robust(m);
  for (size_t k = 0; k < m; ++k) robust[k] = problem.edges[k].robust;
  std::vector<double> c2(m);
  for (size_t k = 0; k < m; ++k) c2[k] = gates.of(problem.edges[k]) * gates.of(problem.edges[k]);
  std::vector<double> r = robustResiduals(at);
  const std::vector<double> w = graduatedTls(
      robust, c2, 1.0,
      [&](const std::vector<double>& wk) {
        GraphProblem weighted = at;
        weighted.edges.clear();
        for (size_t k = 0; k < m; ++k)
          if (wk[k] > 0)
          {
            weighted.edges.push_back(at.edges[k]);
            weighted.edges.back().information *= wk[k];
          }
        optimizeGraphProblem(weighted, step);
        at.poses = weighted.poses;
        r = robustResiduals(at);
      },
      [&](size_t k) { return r[k] * r[k]; });
  std::vector<char> in(m);
  for (size_t k = 0; k < m; ++k) in[k] = w[k] >= 0.5;
  return in;
}

/** Whether `headings` fit every robustified edge's rotation within its gate. */
bool headingsFitEveryEdge(const GraphProblem& problem, const std::vector<double>& headings, const OutlierGates& gates)
{
  for (const auto& e : problem.edges)
  {
    if (!e.robust) continue;
    const double r = std::remainder(headings[e.j] - headings[e.i] - e.z.z(), 2 * M_PI);
    if (r * r / e.information.inverse()(2, 2) > gates.of(e) * gates.of(e)) return false;
  }
  return true;
}

/** Whether LAGO over the edges flagged in `use` (and every edge not robustified) is affordable:
 * its factor's fill per column at most kMaxLagoFill (normal_equations.h's symbolic analysis). */
bool lagoAffordable(const GraphProblem& problem, const std::vector<char>& use)
{
  std::vector<std::pair<int, int>> pairs;
  for (size_t k = 0; k < problem.edges.size(); ++k)
    if (use[k] || !problem.edges[k].robust) pairs.emplace_back(problem.edges[k].i, problem.edges[k].j);
  return NormalEquations::fillPerColumnOf(static_cast<int>(problem.poses.size()), pairs) <= kMaxLagoFill;
}

std::vector<geometry::Pose2> lagoOrGuess(const GraphProblem& problem)
{
  try
  {
    return lagoPoses(problem);
  }
  catch (const std::runtime_error&)
  {
    return problem.poses;  // a singular system (a piece held by nothing): the guess
  }
}

/** The edges flagged in `met` as a problem of their own, with their indices in `problem`. */
GraphProblem metEdges(const GraphProblem& problem, const std::vector<char>& met, std::vector<size_t>& indices)
{
  GraphProblem out = problem;
  out.edges.clear();
  indices.clear();
  for (size_t k = 0; k < problem.edges.size(); ++k)
    if (met[k])
    {
      out.edges.push_back(problem.edges[k]);
      indices.push_back(k);
    }
  return out;
}

/** The state of the pass over the loops in the chain's order: the edges met so far, those kept,
 * and the poses so far. */
struct OrderedPass
{
  std::vector<char> met, inliers;
  std::vector<geometry::Pose2> poses;
};

/** A loop of that pass that did not fit the poses so far and was taken: its place in the order,
 * the pass's state before it, and what taking it cost the other edges met (its gate's square
 * less the cost it saved: little for a loop that closes a drifted cycle, more for a false loop
 * the chain is bent to fit). */
struct Take
{
  size_t position = 0;
  double bending = 0;
  OrderedPass before;
};

/** Decides loop k of that pass (see orderedInliers): kept if it fits the poses so far; else
 * taken if least squares with it lowers the cost over the edges met so far by kOrderMargin of
 * its gate's square. Returns whether it was taken that way, with what the taking cost the
 * others in `bending`. */
bool decideInOrder(const GraphProblem& problem, const OutlierGates& gates, const GraphOptimizerParams& params,
                   size_t k, OrderedPass& pass, double& bending)
{
  pass.met[k] = 1;
  GraphProblem one = problem;
  one.edges = {problem.edges[k]};
  one.poses = pass.poses;
  const double gate2 = gates.of(problem.edges[k]) * gates.of(problem.edges[k]);
  if (robustResiduals(one)[0] <= gates.of(problem.edges[k]))
  {
    pass.inliers[k] = 1;
    return false;
  }
  std::vector<size_t> indices;
  GraphProblem seen = metEdges(problem, pass.met, indices);
  seen.poses = pass.poses;
  const double without = truncatedCost(seen, gates);
  // With it, from LAGO's poses (a loop that closes a drifted cycle) and, if that is not
  // enough, from the poses so far (LAGO's may fit the rest less well).
  std::vector<char> with_all = pass.inliers;
  with_all[k] = 1;
  std::vector<char> with;
  for (const bool from_lago : {true, false})
  {
    with.assign(indices.size(), 0);
    for (size_t u = 0; u < indices.size(); ++u) with[u] = with_all[indices[u]];
    seen.poses = from_lago ? lagoOrGuess(subset(problem, with_all)) : pass.poses;
    if (refineInliers(seen, with, gates, params).status == OptimizationStatus::Diverged) continue;
    const double cost = truncatedCost(seen, gates);
    if (cost > without - kOrderMargin * gate2) continue;
    for (size_t u = 0; u < indices.size(); ++u) pass.inliers[indices[u]] = with[u];
    pass.poses = seen.poses;
    bending = gate2 - (without - cost);
    return true;
  }
  return false;
}

/** The loop candidates taken one at a time in the order of their later end, as a front end
 * meets them, every other edge from the start (decideInOrder): a loop that fits the poses so far
 * within its gate is kept; one that does not is kept if least squares with it (from LAGO's poses
 * on the kept edges and it, then on the edges within their gates: refineInliers) costs less over
 * the edges met so far than the poses so far with it switched off, by kOrderMargin of its gate's
 * square, and then the edges that refinement switched off go too. Where true loops are few and
 * far apart (no neighbour supports them, the guess has drifted beyond what the chain's
 * unwrapping resolves), the chain is what tells a loop that agrees with those kept from one that
 * does not. A decision of that pass is final, so a false loop taken early turns away the true
 * loops that contradict it (MIT with 20 random false loops, seed 17: one taken at node 737, the
 * four true loops after it switched off). So the pass is run again, up to kMaxRetakes times,
 * from before a loop it took: of the kConflictTests takes that bent the others most, the first
 * after which a loop a neighbour supports was turned away that, asked from the state before the
 * take with it switched off, would have been kept. The pass again has that loop and the loops
 * that agree with it (`agreement.runs`) switched off. */
std::vector<Proposal> orderedInliers(const GraphProblem& problem, const OdometryChain& chain,
                                     const LoopAgreement& agreement, const OutlierGates& gates,
                                     const GraphOptimizerParams& params)
{
  const size_t m = problem.edges.size();
  const std::vector<int>& runs = agreement.runs;
  const std::vector<int>& support = agreement.support;
  std::vector<size_t> loops;
  OrderedPass first{std::vector<char>(m), std::vector<char>(m), {}};
  for (size_t k = 0; k < m; ++k)
  {
    if (isLoopCandidate(problem, chain, k))
      loops.push_back(k);
    else
      first.met[k] = first.inliers[k] = 1;
  }
  auto later = [&](size_t k) { return std::max(problem.edges[k].i, problem.edges[k].j); };
  std::stable_sort(loops.begin(), loops.end(), [&](size_t a, size_t b) { return later(a) < later(b); });
  std::vector<size_t> indices;
  GraphProblem chain_only = metEdges(problem, first.met, indices);
  chain_only.poses = lagoOrGuess(chain_only);
  optimizeGraphProblem(chain_only, leastSquares(params));
  first.poses = chain_only.poses;

  // Each pass from the state before the loop the previous one should not have taken.
  std::vector<Proposal> out;
  std::vector<int> forbidden;  // runs of loops switched off
  size_t from = 0;
  OrderedPass pass = first;
  for (size_t retake = 0;; ++retake)
  {
    std::vector<Take> takes;
    std::vector<size_t> refused;  // positions of the loops turned away that a neighbour supports
    for (size_t p = from; p < loops.size(); ++p)
    {
      const size_t k = loops[p];
      if (std::find(forbidden.begin(), forbidden.end(), runs[k]) != forbidden.end())
      {
        pass.met[k] = 1;  // met, switched off
        continue;
      }
      OrderedPass before = pass;
      double bending = 0;
      if (decideInOrder(problem, gates, params, k, pass, bending))
        takes.push_back({p, bending, std::move(before)});
      else if (!pass.inliers[k] && support[k] > 0)
        refused.push_back(p);
    }
    out.push_back({retake == 0 ? "the loops in the chain's order" : "the loops in the chain's order, less a loop taken",
                   pass.inliers, pass.poses});
    if (retake == kMaxRetakes || refused.empty()) break;
    // The takes that bent the others most, each asked whether the first supported loop turned
    // away after it would have been kept without it; the first that would is taken back.
    std::vector<const Take*> order;
    for (const Take& t : takes)
      if (t.position < refused.back()) order.push_back(&t);
    std::stable_sort(order.begin(), order.end(), [](const Take* a, const Take* b) { return a->bending > b->bending; });
    const Take* back = nullptr;
    for (size_t c = 0; c < std::min(order.size(), kConflictTests) && !back; ++c)
    {
      const size_t q = *std::upper_bound(refused.begin(), refused.end(), order[c]->position);
      OrderedPass probe = order[c]->before;
      for (size_t p = order[c]->position; p < q; ++p) probe.met[loops[p]] = 1;  // met, switched off
      double bending = 0;
      decideInOrder(problem, gates, params, loops[q], probe, bending);
      if (probe.inliers[loops[q]]) back = order[c];
    }
    if (!back) break;
    forbidden.push_back(runs[loops[back->position]]);
    from = back->position;
    pass = back->before;
  }
  return out;
}
}  // namespace

OutlierGates outlierGates(const GraphOptimizerParams& params)
{
  return {params.outlier_gate, params.outlier_gate_chain};
}

OptimizationReport refineInliers(GraphProblem& problem, std::vector<char>& inliers, const OutlierGates& gates,
                                 const GraphOptimizerParams& params)
{
  const GraphOptimizerParams l2 = leastSquares(params);
  OptimizationReport total;
  for (int round = 0; round < kMaxRounds; ++round)
  {
    GraphProblem kept = subset(problem, inliers);
    const OptimizationReport r = optimizeGraphProblem(kept, l2);
    total.iterations += r.iterations;
    total.accepted_steps += r.accepted_steps;
    total.status = r.status;
    total.message = r.message;
    if (r.status == OptimizationStatus::Diverged) break;
    problem.poses = kept.poses;
    const std::vector<double> res = robustResiduals(problem);
    std::vector<char> again(inliers.size());
    for (size_t k = 0; k < again.size(); ++k) again[k] = !problem.edges[k].robust || res[k] <= gates.of(problem.edges[k]);
    if (again == inliers) break;
    inliers.swap(again);
  }
  return total;
}

namespace
{
/** A proposal refined: its poses, inliers and truncated cost. */
struct Candidate
{
  std::string name;
  std::vector<geometry::Pose2> poses;
  std::vector<char> inliers;
  double cost = std::numeric_limits<double>::infinity();
  OptimizationReport solve;  ///< its refinement's
};

/** Refines a proposal (refineInliers) and scores it; the cost stays infinite if a solve diverged. */
Candidate refined(const GraphProblem& problem, Proposal p, const OutlierGates& gates, const GraphOptimizerParams& params,
                  size_t& iterations)
{
  GraphProblem at = problem;
  at.poses = p.start;
  Candidate c;
  c.name = p.name;
  c.inliers = std::move(p.inliers);
  c.solve = refineInliers(at, c.inliers, gates, params);
  iterations += c.solve.iterations;
  c.poses = at.poses;
  if (c.solve.status != OptimizationStatus::Diverged) c.cost = truncatedCost(at, gates);
  return c;
}

/** Every edge from LAGO's poses or the guess, whichever starts at the lower chi2, if LAGO's
 * headings fit every edge within its gate (a graph with no outlier); nothing otherwise. */
std::vector<Proposal> everyEdge(const GraphProblem& problem, const OutlierGates& gates)
{
  if (!lagoAffordable(problem, std::vector<char>(problem.edges.size(), 1))) return {};
  GraphProblem lago = problem;
  try
  {
    const std::vector<double> headings = lagoHeadings(problem);
    if (!headingsFitEveryEdge(problem, headings, gates)) return {};
    lago.poses = lagoPositions(problem, headings);
  }
  catch (const std::runtime_error&)
  {
    return {};  // a singular system (a piece held by nothing): no such proposal
  }
  const bool from_lago = graphChi2(lago) < graphChi2(problem);
  return {{from_lago ? "every edge, from LAGO" : "every edge", std::vector<char>(problem.edges.size(), 1),
           from_lago ? lago.poses : problem.poses}};
}

/** The other proposals: the guess's inliers, the locally consistent loops, robust LAGO's (these
 * two where LAGO is affordable). */
std::vector<Proposal> decidedProposals(const GraphProblem& problem, const std::vector<int>& support,
                                       const OutlierGates& gates, const GraphOptimizerParams& params)
{
  std::vector<Proposal> out;
  out.push_back({"the guess's inliers", guessInliers(problem, gates, params), problem.poses});
  std::vector<char> consistent(problem.edges.size());
  for (size_t k = 0; k < consistent.size(); ++k) consistent[k] = support[k] != 0;  // -1: no loop candidate
  if (!lagoAffordable(problem, consistent)) return out;
  out.push_back({"the locally consistent loops", consistent, lagoOrGuess(subset(problem, consistent))});
  // Robust LAGO over the consistent loops, and over every loop where the loops no neighbour
  // supports are few (isolated true loops: a sparse graph, a tracking error only loops far
  // apart reveal).
  size_t unsupported = 0;
  for (const int s : support) unsupported += s == 0;
  std::vector<std::pair<std::string, std::vector<char>>> uses{{"robust LAGO's inliers", consistent}};
  const std::vector<char> every(problem.edges.size(), 1);
  if (unsupported > 0 && unsupported <= kMaxUnsupportedForLago && lagoAffordable(problem, every))
    uses.push_back({"robust LAGO's inliers of every loop", every});
  for (auto& [name, use] : uses)
    try
    {
      RobustLago robust = robustLagoPoses(problem, use, gates);
      out.push_back({name, std::move(robust.inliers), std::move(robust.poses)});
    }
    catch (const std::runtime_error&)
    {
      // A singular linear system (a piece held by switched-off edges only): no such proposal.
    }
  return out;
}

/** The poses whose index lies within kRunWindow of a flagged pose's (pose indices follow the
 * chain in the graphs tracking builds and in the public files). */
std::vector<char> widened(const std::vector<char>& flagged)
{
  const int n = static_cast<int>(flagged.size());
  std::vector<char> out(flagged.size(), 0);
  for (int p = 0; p < n; ++p)
    if (flagged[p])
      for (int q = std::max(0, p - kRunWindow); q <= std::min(n - 1, p + kRunWindow); ++q) out[q] = 1;
  return out;
}

/** Whether edge k is a robustified edge of the chain (no loop candidate: runs[k] < 0). */
bool isChainEdge(const GraphProblem& problem, const std::vector<int>& runs, size_t k)
{
  return runs[k] < 0 && problem.edges[k].robust && problem.edges[k].kind != EdgeKind::Loop;
}

/** Per pose, whether it lies within kRunWindow of a chain edge switched off in `inliers`. */
std::vector<char> nearBrokenChain(const GraphProblem& problem, const std::vector<char>& inliers,
                                  const std::vector<int>& runs)
{
  std::vector<char> broken(problem.poses.size(), 0);
  for (size_t k = 0; k < runs.size(); ++k)
    if (isChainEdge(problem, runs, k) && !inliers[k]) broken[problem.edges[k].i] = broken[problem.edges[k].j] = 1;
  return widened(broken);
}

/** The runs of loops (LoopAgreement::runs) not `tried` yet worth trying without their kept
 * loops (`only_at_break`: of those, the ones at a break of the chain), at most kMaxRunTrials:
 * first those with a kept loop near a switched-off chain edge (a group of false
 * loops the graph broke its chain to take in: they fit, the chain does not), then the most
 * strained (the largest mean squared residual of their kept loops: a group the graph bent itself
 * to take in). Without a run its loops cost their gates, and the other edges at least nothing: a
 * run whose loops' margin below their gates exceeds the chi2 of the other kept edges cannot
 * lower the cost, and is not tried. */
std::vector<int> strainedRuns(const GraphProblem& problem, const Candidate& best, const std::vector<int>& runs,
                              const OutlierGates& gates, const std::vector<int>& tried, bool only_at_break)
{
  int count = 0;
  for (const int r : runs) count = std::max(count, r + 1);
  std::vector<double> strain(count, 0), margin(count, 0);
  std::vector<int> kept(count, 0);
  GraphProblem at = problem;
  at.poses = best.poses;
  const std::vector<double> res = robustResiduals(at);
  double kept_chi2 = graphChi2(at);
  for (size_t k = 0; k < runs.size(); ++k)
    if (!best.inliers[k]) kept_chi2 -= res[k] * res[k];
  for (size_t k = 0; k < runs.size(); ++k)
  {
    if (runs[k] < 0 || !best.inliers[k]) continue;
    const double g = gates.of(problem.edges[k]);
    strain[runs[k]] += res[k] * res[k];
    margin[runs[k]] += g * g - res[k] * res[k];
    ++kept[runs[k]];
  }
  // A run with a kept loop near a switched-off chain edge first: the graph broke its chain to
  // take a group of false loops in, which then fit (they are not strained).
  const std::vector<char> broken = nearBrokenChain(problem, best.inliers, runs);
  std::vector<char> at_break(count, 0);
  for (size_t k = 0; k < runs.size(); ++k)
    if (runs[k] >= 0 && best.inliers[k] && (broken[problem.edges[k].i] || broken[problem.edges[k].j]))
      at_break[runs[k]] = 1;
  std::vector<int> order;
  for (int run = 0; run < count; ++run)
    if (kept[run] > 0 && margin[run] < kept_chi2 - strain[run] && (at_break[run] || !only_at_break) &&
        std::find(tried.begin(), tried.end(), run) == tried.end())
      order.push_back(run);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (at_break[a] != at_break[b]) return at_break[a] > at_break[b];
    return strain[a] / kept[a] > strain[b] / kept[b];
  });
  if (order.size() > kMaxRunTrials) order.resize(kMaxRunTrials);
  return order;
}

/** The edges switched off but within kNearGates of their gate at the best result, and those
 * within kFlipGates that least squares would take in for less than their gate's square (to
 * first order: single_flip.h), tried back together: a true loop that closes a cycle no proposal
 * brought near (least squares without it relaxes the cycle away) lies a few gates off, or
 * further where the graph bends easily to it (a sparse walk of 800 poses with 60 random false
 * loops: a true loop 4.3 gates off, worth 19.6 less kept); a false loop, tens to hundreds. The
 * lower cost stays in `best`. */
void tryNearEdges(const GraphProblem& problem, const OutlierGates& gates, const GraphOptimizerParams& params,
                  Candidate& best, size_t& iterations)
{
  GraphProblem at = problem;
  at.poses = best.poses;
  const std::vector<double> res = robustResiduals(at);
  std::vector<char> with = best.inliers;
  std::vector<size_t> farther;
  for (size_t k = 0; k < with.size(); ++k)
  {
    if (with[k]) continue;
    if (res[k] <= kNearGates * gates.of(problem.edges[k]))
      with[k] = 1;
    else if (res[k] <= kFlipGates * gates.of(problem.edges[k]))
      farther.push_back(k);
  }
  if (!farther.empty()) try
    {
      const std::vector<double> change = singleFlipChanges(at, best.inliers, farther, gates);
      for (size_t u = 0; u < farther.size(); ++u)
        if (change[u] < 0) with[farther[u]] = 1;
    }
    catch (const std::runtime_error&)
    {
      // The kept edges' normal matrix cannot be factored: the near edges only.
    }
  if (with == best.inliers) return;
  Candidate c = refined(problem, {best.name + ", with the edges near their gates", std::move(with), best.poses}, gates,
                        params, iterations);
  if (c.cost < best.cost) best = std::move(c);
}

/** Each strained run of loops that agree with each other (a group of false loops of which a few
 * fit) tried without its kept loops, and with the chain edges switched off near them taken back
 * (on the 3500-node grid with 1000 grouped false loops, three of a group were kept where five
 * consecutive edges beside them were off: 0.92 m from the clean optimum, which either change
 * alone did not mend), or, tried too where they differ, the chain edges switched off that bound
 * the pieces of chain holding its kept loops' ends (CSAIL with 13 grouped false loops, seed 15:
 * three kept where the graph cut the chain 80 poses from their ends, 24 m from the clean
 * optimum); the lower cost stays in `best`. A result that a trial lowered may have a
 * run of its own at a break of the chain, which is tried next (kMaxRunRounds): on a sparse
 * 800-pose walk with 60 grouped false loops, a false loop holding a piece of chain cut off at
 * both ends came to be at a break only after ten other runs had gone. The later rounds try only
 * such runs: each trial is a least-squares solve of the whole graph (the 3500-node grid with
 * 100 false loops took 7.9 s of CPU with every strained run tried again, against 2.6). */
void tryWithoutStrainedRuns(const GraphProblem& problem, const std::vector<int>& runs, const OutlierGates& gates,
                            const GraphOptimizerParams& params, Candidate& best, size_t& iterations)
{
  std::vector<int> tried;
  for (size_t round = 0; round < kMaxRunRounds; ++round)
  {
    const double before = best.cost;
    std::vector<int> order = strainedRuns(problem, best, runs, gates, tried, round > 0);
    for (const int run : order)
    {
      tried.push_back(run);
      std::vector<char> without = best.inliers;
      for (size_t k = 0; k < without.size(); ++k)
        if (runs[k] == run) without[k] = 0;
      // The chain edges switched off near the run's kept loops' ends come back with it gone;
      // and, tried too where they differ, those that bound the pieces of chain holding the
      // ends (the last cut before each end and the first after it: a run of false loops may
      // hold a long piece the graph cut off to take it in).
      std::vector<char> kept_ends(problem.poses.size(), 0);
      for (size_t k = 0; k < without.size(); ++k)
        if (runs[k] == run && best.inliers[k]) kept_ends[problem.edges[k].i] = kept_ends[problem.edges[k].j] = 1;
      const std::vector<char> near_ends = widened(kept_ends);
      std::vector<std::pair<int, size_t>> cuts;  // (the cut's earlier pose, edge) of the chain edges off
      for (size_t k = 0; k < without.size(); ++k)
        if (isChainEdge(problem, runs, k) && !without[k])
          cuts.emplace_back(std::min(problem.edges[k].i, problem.edges[k].j), k);
      std::sort(cuts.begin(), cuts.end());
      std::vector<char> near = without, bounding = without;
      for (const auto& [pose, k] : cuts)
        if (near_ends[problem.edges[k].i] || near_ends[problem.edges[k].j]) near[k] = 1;
      for (int p = 0; p < static_cast<int>(kept_ends.size()); ++p)
      {
        if (!kept_ends[p]) continue;
        const auto after = std::lower_bound(cuts.begin(), cuts.end(), std::make_pair(p, size_t{0}));
        if (after != cuts.end()) bounding[after->second] = 1;
        if (after != cuts.begin()) bounding[std::prev(after)->second] = 1;
      }
      std::vector<std::vector<char>> trials{near};
      if (bounding != near) trials.push_back(bounding);
      for (std::vector<char>& trial : trials)
      {
        Candidate c = refined(problem, {best.name + ", less a run of loops", std::move(trial), best.poses}, gates,
                              params, iterations);
        if (c.cost < best.cost) best = std::move(c);
      }
    }
    if (!(best.cost < before)) break;  // the strained runs of an unchanged result were all tried
  }
}

/** Whether the chi2 of every edge at the problem's poses is within the 0.999 quantile of the
 * chi-square distribution of a least-squares optimum whose edges all hold (3 degrees of freedom
 * per edge, less 3 per free pose). */
bool chi2Plausible(const GraphProblem& problem)
{
  size_t components = 0;
  const std::vector<int> var = variableIndex(problem, components);
  const int free = static_cast<int>(std::count_if(var.begin(), var.end(), [](int v) { return v >= 0; }));
  const int dof = 3 * static_cast<int>(problem.edges.size()) - 3 * free;
  return dof > 0 && graphChi2(problem) <= mrpt::math::chi2inv(0.999, dof);
}

/** Whether switching off no single loop of the best result lowers the truncated cost, to first
 * order (single_flip.h), and its chi2 is plausible (chi2Plausible): asked of the least-squares
 * optimum of every edge when each is within its gate. Then no false loop there is worth
 * switching off, and the pass in the chain's order is not run (on a clean graph with few loops
 * it was most of the time: MIT, 0.2 s against 0.02 s). The chi2 guards against false loops that
 * mask each other, as one-at-a-time diagnostics allow: several that agree, each within its gate
 * with the chain bent to fit them, none worth switching off alone (not met on the graphs
 * measured). */
bool noLoopSwitchLowersCost(const GraphProblem& problem, const OdometryChain& chain, const OutlierGates& gates,
                            const Candidate& best)
{
  if (best.name.empty()) return false;
  GraphProblem at = problem;
  at.poses = best.poses;
  if (!chi2Plausible(at)) return false;
  std::vector<size_t> loops;
  for (size_t k = 0; k < problem.edges.size(); ++k)
    if (isLoopCandidate(problem, chain, k)) loops.push_back(k);
  try
  {
    const std::vector<double> change = singleFlipChanges(at, best.inliers, loops, gates);
    return std::all_of(change.begin(), change.end(), [](double c) { return c >= 0; });
  }
  catch (const std::runtime_error&)
  {
    return false;
  }
}
}  // namespace

OptimizationReport optimizeTruncated(GraphProblem& problem, const GraphOptimizerParams& params)
{
  mrpt::system::CTicTac timer;
  params.check();
  checkProblem(problem);
  const size_t m = problem.edges.size();
  const OutlierGates gates = outlierGates(params);
  size_t iterations = 0, proposals = 0;
  Candidate best;
  // A proposal whose inliers are a set a refinement already ended at is not refined again:
  // least squares on the same edges ends at the same poses (three of CSAIL's five proposals
  // with 13 false loops).
  std::vector<std::vector<char>> ended_at;
  auto consider = [&](Proposal p) {
    ++proposals;
    for (size_t k = 0; k < m; ++k) p.inliers[k] = p.inliers[k] || !problem.edges[k].robust;
    if (std::find(ended_at.begin(), ended_at.end(), p.inliers) != ended_at.end()) return;
    Candidate c = refined(problem, std::move(p), gates, params, iterations);
    ended_at.push_back(c.inliers);
    if (c.cost < best.cost) best = std::move(c);
  };
  for (Proposal& p : everyEdge(problem, gates)) consider(std::move(p));
  // Every edge within its gate at the least-squares optimum: nothing to decide where loops are
  // many. Where they are few, least squares can bend a weak chain to fit a false loop within the
  // gates, and the loops are also taken in the chain's order, unless switching no loop off would
  // lower the cost.
  const bool clean = best.cost < std::numeric_limits<double>::infinity() &&
                     std::all_of(best.inliers.begin(), best.inliers.end(), [](char in) { return in != 0; });
  const OdometryChain chain = odometryChain(problem);
  size_t loops = 0;
  for (size_t k = 0; k < m; ++k) loops += isLoopCandidate(problem, chain, k);
  const LoopAgreement agreement = loopAgreement(problem, chain);
  if (loops <= kMaxLoopsForOrder && !(clean && noLoopSwitchLowersCost(problem, chain, gates, best)))
    for (Proposal& p : orderedInliers(problem, chain, agreement, gates, params)) consider(std::move(p));
  if (!clean)
  {
    for (Proposal& p : decidedProposals(problem, agreement.support, gates, params)) consider(std::move(p));
    if (!best.name.empty()) tryNearEdges(problem, gates, params, best, iterations);
    if (!best.name.empty()) tryWithoutStrainedRuns(problem, agreement.runs, gates, params, best, iterations);
    // Without a run, the true loops its false ones pushed away may lie near their gates.
    if (!best.name.empty()) tryNearEdges(problem, gates, params, best, iterations);
  }
  OptimizationReport rep = best.solve;
  rep.edges = m;
  rep.iterations = iterations;
  rep.initial_chi2 = graphChi2(problem);
  rep.initial_cost = truncatedCost(problem, gates);
  rep.kernels = uniformKernels({2.0, params.kernel_c});
  rep.time_s = timer.Tac();
  if (best.name.empty())
  {
    rep.status = OptimizationStatus::Diverged;
    rep.message = "truncated least squares: the least-squares solve of every proposal diverged";
    return rep;
  }
  problem.poses = best.poses;
  rep.start = best.name;
  rep.final_chi2 = graphChi2(problem);
  rep.final_cost = best.cost;
  const std::vector<double> res = robustResiduals(problem);
  for (size_t k = 0; k < m; ++k)
    if (problem.edges[k].robust && res[k] > gates.of(problem.edges[k])) rep.switched_off.push_back(k);
  rep.message = "truncated least squares from " + best.name + " (" + std::to_string(proposals) +
                " proposals): " + best.solve.message;
  return rep;
}

}  // namespace swslam::graph
