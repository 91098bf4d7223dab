#include "swslam/system/run_outputs.h"

#include "swslam/atomic_file.h"
#include "swslam/eval/report.h"
#include "swslam/graph_io.h"

#include <filesystem>
#include <functional>
#include <unordered_map>

namespace swslam
{
RunSummary summarizeRun(const RunResults& results, double wall_time,
                        const std::vector<StampedPose>* ground_truth, double max_dt)
{
  RunSummary s;
  s.scans = results.stats.size();
  s.skipped_scans = results.skipped;
  s.nodes = results.graph.nodeCount();
  s.constraints = results.graph.edgeCount();
  s.loops = results.loops;
  s.refinement_pairs = results.refinement_pairs;
  s.refinement_edges = results.refinement_edges;
  for (const ScanStats& r : results.stats)
    if (r.source == TrackingSource::Odometry || r.source == TrackingSource::ConstantMotion)
      s.fallback_scans++;
  for (size_t i = 1; i < results.trajectory.size(); ++i)
    s.distance += (results.trajectory[i].pose.translation() - results.trajectory[i - 1].pose.translation()).norm();
  if (results.trajectory.size() > 1)
    s.duration = results.trajectory.back().t - results.trajectory.front().t;
  s.wall_time = wall_time;
  s.map_bytes = results.map_bytes;
  s.matching = summarizeTimes(results.stats, &ScanStats::match_ms, false);
  s.tracking = summarizeTimes(results.stats, &ScanStats::tracking_ms, true);
  s.graph = summarizeTimes(results.stats, &ScanStats::graph_ms, false);
  s.map = summarizeTimes(results.stats, &ScanStats::map_ms, false);
  if (ground_truth)
  {
    const eval::TrajectoryEvaluation e =
        eval::evaluateTrajectory(results.trajectory, *ground_truth, max_dt, 1.0);
    s.ate_rmse = e.ate.position.rmse;
    s.rpe_step_rmse = e.rpe_step.translation.rmse;
    s.rpe_metre_rmse = e.rpe_segment.translation.rmse;
  }
  return s;
}

RenderInput renderInputOf(const RunResults& results)
{
  RenderInput in;
  for (const StampedPose& p : results.trajectory) in.trajectory.push_back(p.pose);
  std::unordered_map<PoseGraph::TNodeID, size_t> index;
  for (const auto id : results.graph.nodeIds())
  {
    index[id] = in.nodes.size();
    in.nodes.push_back(results.graph.pose(id));
  }
  for (size_t i = 0; i < results.graph.edgeCount(); ++i)
  {
    const PoseGraph::Edge& e = results.graph.edge(i);
    in.edges.emplace_back(index.at(e.from), index.at(e.to));
  }
  return in;
}

std::vector<OutputProblem> writeRunOutputs(const std::string& dir, const RunResults& results,
                                           const mrpt::maps::COccupancyGridMap2D& grid,
                                           const MapParams& map_params, const std::string& summary,
                                           bool render)
{
  const RenderInput render_input = renderInputOf(results);
  std::vector<OutputProblem> problems =
      writeMapOutputs(dir, grid, map_params, render ? &render_input : nullptr);
  const std::filesystem::path d(dir);
  auto attempt = [&](const char* file, const std::function<void(const std::string&)>& write) {
    try
    {
      write((d / file).string());
    }
    catch (const std::exception& e)
    {
      problems.push_back({file, e.what()});
    }
  };
  attempt("trajectory.tum", [&](const std::string& p) { writeTum(p, results.trajectory); });
  attempt("keyframes.tum", [&](const std::string& p) { writeTum(p, results.keyframes); });
  attempt("graph.graph", [&](const std::string& p) { saveGraph(results.graph, p); });
  attempt("stats.csv", [&](const std::string& p) { writeTextAtomically(p, formatStatsCsv(results.stats)); });
  attempt("summary.md", [&](const std::string& p) { writeTextAtomically(p, summary); });
  return problems;
}

}  // namespace swslam
