#include <swslam/bench/false_loops.h>

#include <swslam/graph/outlier_decision.h>
#include <swslam/graph/sliding_window.h>
#include <swslam/graph/synthetic.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <set>

namespace swslam::bench
{
namespace
{
RobustMethod oursWith(const std::string& name, const graph::GraphOptimizerParams& params)
{
  return {name, [params, name](const graph::PoseGraph& g, std::vector<size_t>& off) {
            SolverRun run{name, 0, 0, 0, g};
            timeSolver(1, [&] {
              run.result = g;
              const graph::OptimizationReport r = graph::optimizeFull(run.result, params);
              run.iterations = r.iterations;
              off = r.switched_off;
            }, run);
            return run;
          },
          {}};
}
}  // namespace

double targetCost(const graph::PoseGraph& graph, const graph::GraphOptimizerParams& params)
{
  return graph::robustCost(graph::fullSubproblem(graph, params).problem, graph::uniformKernels(params.kernel()));
}

std::vector<size_t> switchedOffEdges(const graph::PoseGraph& graph, const graph::GraphOptimizerParams& params)
{
  const graph::GraphSubproblem sub = graph::fullSubproblem(graph, params);
  std::vector<size_t> off = graph::switchedOffEdges(sub.problem, params);
  for (size_t& k : off) k = sub.edge_indices[k];
  return off;
}

std::vector<RobustMethod> ourRobustMethods(const graph::GraphOptimizerParams& params)
{
  graph::GraphOptimizerParams l2 = params, fixed = params, gnc = params, adaptive = params, tls = params;
  l2.kernel_alpha = 2;
  l2.kernel_schedule = fixed.kernel_schedule = graph::KernelSchedule::Fixed;
  gnc.robust_consecutive = false;
  gnc.kernel_schedule = graph::KernelSchedule::Gnc;
  adaptive.kernel_schedule = graph::KernelSchedule::Adaptive;
  tls.kernel_schedule = graph::KernelSchedule::Tls;
  RobustMethod truncated = oursWith("tls", tls);
  truncated.objective = [tls](const graph::PoseGraph& g) {
    return graph::truncatedCost(graph::fullSubproblem(g, tls).problem, graph::outlierGates(tls));
  };
  return {oursWith("least-squares", l2), oursWith("fixed", fixed), oursWith("gnc", gnc),
          oursWith("adaptive", adaptive), truncated};
}

std::vector<RobustMethod> selectMethods(const std::vector<RobustMethod>& methods, const std::vector<std::string>& names)
{
  for (const std::string& n : names)
    if (std::none_of(methods.begin(), methods.end(), [&](const RobustMethod& m) { return m.name == n; }))
      throw std::invalid_argument("no method named '" + n + "'");
  std::vector<RobustMethod> out;
  for (const RobustMethod& m : methods)
    if (std::find(names.begin(), names.end(), m.name) != names.end()) out.push_back(m);
  return out;
}

std::vector<FalseLoopCase> falseLoopCases(const std::string& name, const graph::PoseGraph& clean,
                                          const std::vector<size_t>& counts, const graph::GraphOptimizerParams& params,
                                          const std::vector<RobustMethod>& methods, std::FILE* progress,
                                          unsigned seed)
{
  graph::PoseGraph optimum = clean;
  // The reference: least squares run until the steps vanish, not to a relative tolerance, so
  // that it is the optimum itself and not one of the points near it where a solver may stop.
  graph::GraphOptimizerParams l2;
  l2.kernel_alpha = 2;
  l2.relative_cost_tolerance = 1e-15;
  l2.max_iterations = 1000;
  graph::optimizeFull(optimum, l2);
  const std::vector<geometry::Pose2> clean_poses = graph::truthFromGraph(optimum);
  const double optimum_chi2 = chi2Of(optimum);
  std::vector<FalseLoopCase> out;
  for (const size_t n : counts)
    for (const bool grouped : {false, true})
    {
      if (n == 0 && grouped) continue;
      graph::PoseGraph g = clean;
      graph::FalseLoopOptions fo;
      fo.count = n;
      fo.grouped = grouped;
      fo.seed = seed;
      const std::vector<size_t> added = graph::addFalseLoops(g, fo);
      // The graph with its false loops, at the outlier-free optimum.
      graph::PoseGraph clean_with_false = g;
      for (const auto id : clean_with_false.nodeIds()) clean_with_false.setPose(id, optimum.pose(id));
      const std::set<size_t> truth(added.begin(), added.end());
      for (const RobustMethod& m : methods)
      {
        auto objective = [&](const graph::PoseGraph& at) {
          return m.objective ? m.objective(at) : targetCost(at, params);
        };
        std::vector<size_t> off;
        const SolverRun r = m.run(g, off);
        FalseLoopCase c{name, m.name, n, grouped};
        c.rmse_to_clean = graph::compareToTruth(r.result, clean_poses).rmse_xy;
        graph::PoseGraph on_clean = clean;  // the result's poses against the true edges only
        for (const auto id : on_clean.nodeIds()) on_clean.setPose(id, r.result.pose(id));
        c.clean_chi2_excess = chi2Of(on_clean) / optimum_chi2 - 1.0;
        c.target_cost_ratio = objective(r.result) / objective(clean_with_false);
        size_t hits = 0;
        for (const size_t k : off) hits += truth.count(k);
        c.switched_off = off.size();
        c.precision = off.empty() ? 1.0 : static_cast<double>(hits) / static_cast<double>(off.size());
        c.recall = truth.empty() ? 1.0 : static_cast<double>(hits) / static_cast<double>(truth.size());
        c.time_s = r.time_s;
        c.cpu_s = r.cpu_s;
        c.iterations = r.iterations;
        out.push_back(c);
        if (progress)
        {
          std::fprintf(progress, "%s\n", formatCase(c).c_str());
          std::fflush(progress);
        }
      }
    }
  return out;
}

std::string formatCase(const FalseLoopCase& c)
{
  char buf[320];
  std::snprintf(buf, sizeof(buf),
                "%-22s %-14s loops=%-5zu %-7s rmse_to_clean_m=%-10.4g clean_chi2_excess=%-9.2e cost_vs_clean=%-7.3g off=%-5zu precision=%.3f recall=%.3f time_s=%.3f cpu_s=%.3f iters=%zu",
                c.graph.c_str(), c.method.c_str(), c.false_loops, c.grouped ? "grouped" : "random", c.rmse_to_clean, c.clean_chi2_excess, c.target_cost_ratio,
                c.switched_off, c.precision, c.recall, c.time_s, c.cpu_s, c.iterations);
  return buf;
}

}  // namespace swslam::bench
