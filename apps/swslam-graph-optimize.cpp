// Optimizes a whole pose-graph file (MRPT .graph, g2o or TORO) with the robust
// Levenberg-Marquardt optimizer and writes the result in g2o form.
#include "cli.h"
#include <swslam/graph/io.h>
#include <swslam/graph/sliding_window.h>
#include <swslam/app/config.h>


#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv)
{
  try
  {
    TCLAP::CmdLine cmd("swslam-graph-optimize", ' ', "0.1");
    TCLAP::ValueArg<std::string> in("i", "input", "input graph (.graph, .g2o, TORO)", true, "", "IN", cmd);
    TCLAP::ValueArg<std::string> out("o", "output", "output graph (g2o form)", true, "", "OUT", cmd);
    TCLAP::ValueArg<std::string> config("", "config", "ini file with a [graph_optimizer] section",
                                        false, "", "INI", cmd);
    TCLAP::ValueArg<std::string> alpha("", "alpha", "kernel shape in [-inf, 2] (robustified edges)",
                                       false, "", "A", cmd);
    TCLAP::ValueArg<double> c("", "c", "kernel scale (standard deviations)", false, 0, "C", cmd);
    TCLAP::ValueArg<long long> iters("", "max-iters", "Levenberg-Marquardt iterations", false, 0, "N", cmd);
    using swslam::graph::KernelSchedule;
    std::vector<std::string> schedules;
    for (const auto s : {KernelSchedule::Fixed, KernelSchedule::Gnc, KernelSchedule::Adaptive, KernelSchedule::Tls})
      schedules.push_back(swslam::graph::kernelScheduleName(s));
    TCLAP::ValuesConstraint<std::string> schedule_names(schedules);
    TCLAP::ValueArg<std::string> kernel("", "kernel", "fixed: the kernel from the start; gnc: graduated "
                                        "non-convexity down to it; adaptive: shape and scale per edge kind "
                                        "from the residuals; tls: the outliers decided together, truncated "
                                        "least squares ([graph_optimizer] kernel_schedule)",
                                        false, "", &schedule_names, cmd);
    if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

    swslam::graph::GraphOptimizerParams params;
    if (config.isSet())
      params = swslam::app::loadConfig(config.getValue()).system.graph_optimizer;
    if (alpha.isSet())
    {
      // A string, so that "-inf" (strtod's spelling) is accepted; nothing else may follow.
      const char* text = alpha.getValue().c_str();
      char* end = nullptr;
      params.kernel_alpha = std::strtod(text, &end);
      if (end == text || *end != '\0')
        throw std::invalid_argument("--alpha '" + alpha.getValue() + "' is not a number");
    }
    if (c.isSet()) params.kernel_c = c.getValue();
    if (iters.isSet()) params.max_iterations = swslam::cli::count(iters, 0);
    if (kernel.isSet()) params.kernel_schedule = *swslam::graph::kernelScheduleFromName(kernel.getValue());
    params.check();

    swslam::graph::GraphLoadReport load;
    swslam::graph::PoseGraph graph = swslam::graph::loadGraph(in.getValue(), &load);
    std::printf("loaded %zu vertices, %zu edges, %zu skipped lines\n", load.vertices, load.edges,
                load.skipped_lines);
    for (size_t k = 0; k < load.skipped_lines; ++k)
      std::printf("  skipped line %zu: %s\n", load.skipped_line_numbers[k], load.skip_reasons[k].c_str());
    if (load.placed_vertices > 0)
      std::printf("placed %zu vertices that only edges name, along the odometry chain%s\n", load.placed_vertices,
                  load.placed_pieces > 1 ? (", in " + std::to_string(load.placed_pieces) +
                                            " pieces no edge joins (warning: each held at its own first vertex)")
                                               .c_str()
                                         : "");
    if (load.edges == 0) throw std::runtime_error(in.getValue() + ": the graph has no edges: nothing to optimize");

    const swslam::graph::OptimizationReport r = swslam::graph::optimizeFull(graph, params);
    std::printf("status: %s (%s)\nstart: %s\niterations: %zu\ninitial chi2: %.9g\nfinal chi2: %.9g\n"
                "active squared residuals: %.9g\ntime: %.3f ms\n",
                swslam::graph::statusName(r.status), r.message.c_str(),
                !r.start.empty() ? r.start.c_str() : r.lago_start ? "LAGO" : "the file's poses",
                r.iterations, r.initial_chi2, r.final_chi2, r.active_sq_residuals, 1e3 * r.time_s);
    if (r.components > 1)
      std::printf("warning: the graph falls apart into %zu connected components; each one without a FIX "
                  "node is held at its first node\n", r.components);
    std::array<size_t, swslam::graph::kEdgeKindCount> robust_edges{};
    for (size_t k = 0; k < graph.edgeCount(); ++k)
      if (params.isRobust(graph.edge(k).kind)) ++robust_edges[static_cast<int>(graph.edge(k).kind)];
    if (params.kernel_schedule == KernelSchedule::Adaptive)
      for (int kind = 0; kind < swslam::graph::kEdgeKindCount; ++kind)
        if (robust_edges[kind] > 0)
          std::printf("kernel %s: alpha %.2f, c %.4g\n", swslam::graph::edgeKindName(static_cast<swslam::graph::EdgeKind>(kind)),
                      r.kernels[kind].alpha, r.kernels[kind].c);
    // The edges the kernel distrusts.
    if (params.kernel_schedule == KernelSchedule::Tls)
      std::printf("switched off: %zu edges (beyond their gate: %g for loops, %g for the chain)\n", r.switched_off.size(),
                  params.outlier_gate, params.outlier_gate_chain);
    else
      std::printf("switched off: %zu edges (weight below %g)\n", r.switched_off.size(), params.switched_off_weight);
    for (const size_t k : r.switched_off)
    {
      const auto& e = graph.edge(k);
      std::printf("  edge %zu: %lu -> %lu (%s)\n", k, static_cast<unsigned long>(e.from),
                  static_cast<unsigned long>(e.to), swslam::graph::edgeKindName(e.kind));
    }
    if (r.status == swslam::graph::OptimizationStatus::Diverged) return 2;
    swslam::graph::saveGraph(graph, out.getValue());
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-graph-optimize: " << e.what() << "\n";
    return 1;
  }
}
