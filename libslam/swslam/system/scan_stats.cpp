#include <swslam/system/scan_stats.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace swslam::system
{
std::string formatStatsCsv(const std::vector<ScanStats>& rows)
{
  std::ostringstream out;
  out << "scan,timestamp,source,valid_rays,correspondences,match_sq_residuals,"
         "active_sq_residuals,match_ms,tracking_ms,graph_ms,map_ms,keyframe,new_node,loops,"
         "full_optimization,switched_off,ambiguous,prior_decided\n";
  char line[512];
  for (const ScanStats& r : rows)
  {
    std::snprintf(line, sizeof(line),
                  "%zu,%.6f,%s,%zu,%zu,%.6g,%.6g,%.4f,%.4f,%.4f,%.4f,%zu,%d,%zu,%d,%zu,%d,%d\n", r.scan,
                  r.timestamp, toString(r.source), r.valid_rays, r.correspondences,
                  r.match_sq_residuals, r.active_sq_residuals, r.match_ms, r.tracking_ms,
                  r.graph_ms, r.map_ms, r.keyframe, r.new_node ? 1 : 0, r.loops,
                  r.full_optimization ? 1 : 0, r.switched_off, r.ambiguous, r.prior_decided);
    out << line;
  }
  return out.str();
}

TimeSummary summarizeTimes(const std::vector<ScanStats>& rows, double ScanStats::*field,
                           bool include_zero)
{
  TimeSummary s;
  double sum = 0;
  for (const ScanStats& r : rows)
  {
    const double v = r.*field;
    if (v <= 0 && !include_zero) continue;
    s.count++;
    sum += v;
    s.max_ms = std::max(s.max_ms, v);
  }
  if (s.count > 0) s.avg_ms = sum / s.count;
  return s;
}

namespace
{
std::string timeLine(const char* what, const TimeSummary& t)
{
  char buf[160];
  std::snprintf(buf, sizeof(buf), "| Execution time for %-19s (avg - max) | %.2f - %.2f ms (%zu runs) |\n",
                what, t.avg_ms, t.max_ms, t.count);
  return buf;
}
}  // namespace

std::string formatRunSummary(const RunSummary& s)
{
  std::ostringstream out;
  char buf[200];
  out << "| Table I | |\n|---|---|\n";
  std::snprintf(buf, sizeof(buf), "| Scans processed (skipped) | %zu (%zu) |\n", s.scans, s.skipped_scans);
  out << buf;
  std::snprintf(buf, sizeof(buf), "| Scans tracked by fallback | %zu |\n", s.fallback_scans);
  out << buf;
  std::snprintf(buf, sizeof(buf), "| Ambiguous scans (weak direction or second peak) | %zu |\n", s.ambiguous_scans);
  out << buf;
  std::snprintf(buf, sizeof(buf), "| of them decided by the prediction along a direction | %zu |\n",
                s.prior_decided_scans);
  out << buf;
  std::snprintf(buf, sizeof(buf), "| Number of graph nodes | %zu |\n", s.nodes);
  out << buf;
  std::snprintf(buf, sizeof(buf), "| Number of graph constraints (loops) | %zu (%zu) |\n", s.constraints, s.loops);
  out << buf;
  if (s.refinement_pairs > 0)
  {
    std::snprintf(buf, sizeof(buf), "| Final refinement: pairs matched (edges added) | %zu (%zu) |\n",
                  s.refinement_pairs, s.refinement_edges);
    out << buf;
  }
  std::snprintf(buf, sizeof(buf), "| Travelling distance | %.3f m |\n", s.distance);
  out << buf;
  std::snprintf(buf, sizeof(buf), "| Sensor time / processing time | %.1f s / %.2f s (%.1fx real time) |\n",
                s.duration, s.wall_time, s.wall_time > 0 ? s.duration / s.wall_time : 0.0);
  out << buf;
  std::snprintf(buf, sizeof(buf), "| Map memory (grid, sums, per-node contributions) | %.1f MiB |\n",
                s.map_bytes / 1048576.0);
  out << buf;
  out << timeLine("scan matching", s.matching) << timeLine("local tracking", s.tracking)
      << timeLine("graph optimization", s.graph) << timeLine("map construction", s.map);
  if (s.rpe_step_rmse)
  {
    std::snprintf(buf, sizeof(buf), "| RPE, consecutive scans (rmse) | %.4f m |\n", *s.rpe_step_rmse);
    out << buf;
  }
  if (s.rpe_metre_rmse)
  {
    std::snprintf(buf, sizeof(buf), "| RPE, 1 m segments (rmse) | %.4f m |\n", *s.rpe_metre_rmse);
    out << buf;
  }
  if (s.ate_rmse)
  {
    std::snprintf(buf, sizeof(buf), "| ATE (rmse) | %.4f m |\n", *s.ate_rmse);
    out << buf;
  }
  return out.str();
}

}  // namespace swslam::system
