#include <swslam/app/run_outputs.h>

#include <swslam/app/run_record.h>

#include <swslam/common/atomic_file.h>
#include <swslam/eval/report.h>
#include <swslam/map/change_picture.h>
#include <swslam/graph/io.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <unordered_map>

namespace swslam::app
{
system::RunSummary summarizeRun(const system::RunResults& results, double wall_time,
                        const std::vector<common::StampedPose>* ground_truth, double max_dt)
{
  system::RunSummary s;
  s.scans = results.stats.size();
  s.skipped_scans = results.skipped;
  s.nodes = results.graph.liveNodeCount();
  s.merged_nodes = results.graph.merged().size();
  s.constraints = results.graph.edgeCount();
  s.loops = results.loops;
  s.refinement_pairs = results.refinement_pairs;
  s.refinement_edges = results.refinement_edges;
  for (const system::ScanStats& r : results.stats)
    if (tracking::isFallback(r.source))
      s.fallback_scans++;
    else if (r.ambiguous > 0)
    {
      s.ambiguous_scans++;
      if (r.prior_decided > 0) s.prior_decided_scans++;
    }
  // Along the keyframes, then to the last scan: summed from scan to scan, the distance would
  // add up the matching's jitter (96.996 m on lake-short, whose ground truth travels 92.25 m).
  const auto step = [](const common::StampedPose& a, const common::StampedPose& b) {
    return (b.pose.translation() - a.pose.translation()).norm();
  };
  for (size_t i = 1; i < results.keyframes.size(); ++i) s.distance += step(results.keyframes[i - 1], results.keyframes[i]);
  if (!results.keyframes.empty() && !results.trajectory.empty())
    s.distance += step(results.keyframes.back(), results.trajectory.back());
  if (results.trajectory.size() > 1)
    s.duration = results.trajectory.back().t - results.trajectory.front().t;
  s.wall_time = wall_time;
  s.map_bytes = results.map_bytes;
  s.matching = system::summarizeTimes(results.stats, &system::ScanStats::match_ms, false);
  s.tracking = system::summarizeTimes(results.stats, &system::ScanStats::tracking_ms, true);
  s.graph = system::summarizeTimes(results.stats, &system::ScanStats::graph_ms, false);
  s.map = system::summarizeTimes(results.stats, &system::ScanStats::map_ms, false);
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

map::Overlay overlayOf(const system::RunResults& results)
{
  map::Overlay in;
  for (const common::StampedPose& p : results.trajectory) in.trajectory.push_back(p.pose);
  // One stats row per trajectory pose (the scans tracked, in order): mark those the
  // prediction placed.
  if (results.stats.size() == results.trajectory.size())
    for (const system::ScanStats& r : results.stats) in.by_prediction.push_back(r.placedByPrediction());
  std::unordered_map<graph::PoseGraph::TNodeID, size_t> index;
  for (const auto id : results.graph.nodeIds())
  {
    index[id] = in.nodes.size();
    in.nodes.push_back(results.graph.pose(id));
  }
  for (size_t i = 0; i < results.graph.edgeCount(); ++i)
  {
    const graph::PoseGraph::Edge& e = results.graph.edge(i);
    map::EdgeLook look = map::EdgeLook::Consecutive;
    switch (e.kind)
    {
      case graph::EdgeKind::Consecutive: look = map::EdgeLook::Consecutive; break;
      case graph::EdgeKind::DenseNeighbour: look = map::EdgeLook::DenseNeighbour; break;
      case graph::EdgeKind::Loop: look = map::EdgeLook::Loop; break;
      case graph::EdgeKind::OdometryPrior: look = map::EdgeLook::Prior; break;
    }
    in.edges.push_back({index.at(e.from), index.at(e.to), look, false});
  }
  for (const size_t i : results.switched_off)
    if (i < in.edges.size()) in.edges[i].switched_off = true;
  return in;
}

void writeChangeOutputs(const std::string& dir, const mrpt::maps::COccupancyGridMap2D& grid, const map::Overlay& overlay,
                        const map::ChangeReport& changes, std::vector<map::OutputProblem>& problems)
{
  const std::filesystem::path d(dir);
  try
  {
    common::writeTextAtomically((d / kChangeTable).string(), map::formatChangeReport(changes));
  }
  catch (const std::exception& e)
  {
    problems.push_back({kChangeTable, e.what()});
  }
  try
  {
    map::writeChangePicture(grid, overlay, changes, (d / kChangePicture).string());
  }
  catch (const std::exception& e)
  {
    problems.push_back({kChangePicture, e.what()});
  }
}

std::vector<std::string> runOutputFiles()
{
  return {"map.gridmap.gz", "map.png", "map.yaml", "map.pgm", "map.bt", "render.png",
          "trajectory.tum", "keyframes.tum", "graph.graph", "stats.csv", "summary.md", kRunRecordFile,
          kChangeTable, kChangePicture};
}

std::string outputsLine(const std::string& dir, bool render)
{
  const std::vector<std::string> main = {"map.png", "render.png", "trajectory.tum", "stats.csv", "summary.md"};
  std::string shown, missing;
  for (const std::string& name : runOutputFiles())
  {
    if ((name == "render.png" && !render) || name == kChangeTable || name == kChangePicture) continue;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(std::filesystem::path(dir) / name, ec))
      missing += (missing.empty() ? "" : ", ") + name;
    else if (std::find(main.begin(), main.end(), name) != main.end())
      shown += (shown.empty() ? "" : ", ") + name;
  }
  std::string line = "# outputs in " + dir + "/";
  if (!shown.empty()) line += " (" + shown + ")";
  if (!missing.empty()) line += "; not written: " + missing;
  return line + "\n";
}

std::vector<map::OutputProblem> writeRunOutputs(const std::string& dir, const system::RunResults& results,
                                           const mrpt::maps::COccupancyGridMap2D& grid,
                                           const map::MapParams& map_params, const std::string& summary,
                                           const std::string& run_record, bool render)
{
  std::vector<map::OutputProblem> problems = map::writeMapOutputs(dir, grid, map_params, overlayOf(results), render);
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
  attempt("trajectory.tum", [&](const std::string& p) { common::writeTum(p, results.trajectory); });
  attempt("keyframes.tum", [&](const std::string& p) { common::writeTum(p, results.keyframes); });
  attempt("graph.graph", [&](const std::string& p) {
    common::writeStreamAtomically(p, [&](std::ostream& out) { graph::writeGraph(results.graph, out, results.switched_off); });
  });
  attempt("stats.csv", [&](const std::string& p) { common::writeTextAtomically(p, system::formatStatsCsv(results.stats)); });
  attempt("summary.md", [&](const std::string& p) { common::writeTextAtomically(p, summary); });
  attempt(kRunRecordFile, [&](const std::string& p) { common::writeTextAtomically(p, run_record); });
  return problems;
}

}  // namespace swslam::app
