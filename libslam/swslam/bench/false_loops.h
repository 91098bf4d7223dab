#pragma once
// Robust back ends against false loop closures (doc/graph-optimization.md): a graph's
// outlier-free optimum, then the same graph with N false loops added (random, or grouped as the
// Vertigo benchmark), optimized from the odometry guess by each method. Per case: the distance
// to the outlier-free optimum, precision and recall of the edges switched off, time.

#include <swslam/bench/graph_solvers.h>
#include <swslam/graph/optimizer_params.h>
#include <swslam/graph/pose_graph.h>

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace swslam::bench
{
/** One method: a name, how it optimizes (it returns the edges it switched off) and, if it
 * minimizes a cost of its own (TLS), that cost (empty: the target kernel's, targetCost). */
struct RobustMethod
{
  std::string name;
  std::function<SolverRun(const graph::PoseGraph& graph, std::vector<size_t>& switched_off)> run;
  std::function<double(const graph::PoseGraph& graph)> objective;
};

/** The robustified edges of `graph` whose weight under params' kernel is below
 * params.switched_off_weight at its poses (for solvers that do not report them). */
std::vector<size_t> switchedOffEdges(const graph::PoseGraph& graph, const graph::GraphOptimizerParams& params);

/** The cost params' kernel gives the graph at its poses (every robustified kind alike). */
double targetCost(const graph::PoseGraph& graph, const graph::GraphOptimizerParams& params);

/** Ours: least squares, the fixed kernel of `params` (its robustified kinds), and graduated
 * non-convexity to the same kernel with the odometry chain trusted (consecutive edges not
 * robustified: the loops are what may be false). */
std::vector<RobustMethod> ourRobustMethods(const graph::GraphOptimizerParams& params);

/** The methods named in `names`, in their order in `methods`; throws std::invalid_argument for
 * a name no method has. */
std::vector<RobustMethod> selectMethods(const std::vector<RobustMethod>& methods, const std::vector<std::string>& names);

struct FalseLoopCase
{
  std::string graph, method;
  size_t false_loops = 0;
  bool grouped = false;
  double rmse_to_clean = 0;   ///< [m] node positions against the outlier-free optimum
  /** chi2 of the true edges at the result, relative to the optimum's, minus 1 (0: as good). */
  double clean_chi2_excess = 0;
  /** The method's objective (its own, else the target kernel's) for the graph with its false
   * loops at the result, over the same at the outlier-free optimum: below 1, the objective
   * itself prefers the result, and no search for its minimum can end at the clean graph. */
  double target_cost_ratio = 1;
  double precision = 1, recall = 1;  ///< of the switched-off edges against the false loops
  size_t switched_off = 0;
  double time_s = 0;
  double cpu_s = 0;  ///< process CPU time (steadier than time_s on a busy machine)
  size_t iterations = 0;  ///< the method's linear solves (Ceres: its iterations)
};

/** The outlier-free optimum of `clean` (least squares from its guess), then every count of
 * `counts` false loops (drawn with `seed`), random and grouped, by every method; `params` is
 * the target kernel the costs are measured with. Each case is also printed to `progress` as it
 * ends, if given. */
std::vector<FalseLoopCase> falseLoopCases(const std::string& name, const graph::PoseGraph& clean,
                                          const std::vector<size_t>& counts,
                                          const graph::GraphOptimizerParams& params,
                                          const std::vector<RobustMethod>& methods,
                                          std::FILE* progress = nullptr, unsigned seed = 7);

/** One line per case: graph, method, false loops, random or grouped, then the fields by name. */
std::string formatCase(const FalseLoopCase& c);

}  // namespace swslam::bench
