#include <swslam/system/scan_stats.h>

#include <mrpt/core/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace swslam::system
{
namespace
{
const char* const kStatsHeader =
    "scan,timestamp,source,valid_rays,correspondences,match_sq_residuals,active_sq_residuals,match_ms,"
    "tracking_ms,graph_ms,map_ms,keyframe,new_node,loops,full_optimization,switched_off,ambiguous,prior_decided";
/** The header of files written before the last column (prior_decided) existed. */
std::string olderStatsHeader()
{
  const std::string h = kStatsHeader;
  return h.substr(0, h.rfind(','));
}

/** One row's values, in the header's order: each read whole, or an error naming its column. */
class CsvFields
{
 public:
  CsvFields(const std::string& line, const std::vector<std::string>& names) : names_(names)
  {
    std::stringstream in(line);
    for (std::string f; std::getline(in, f, ',');) fields_.push_back(f);
    if (!line.empty() && line.back() == ',') fields_.emplace_back();
    if (fields_.size() != names_.size())
      throw std::runtime_error(std::to_string(fields_.size()) + " values, expected " + std::to_string(names_.size()));
  }
  double number(size_t k) const
  {
    const std::string& f = fields_.at(k);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(f.c_str(), &end);
    if (f.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v)) fail(k, "is not a finite number");
    return v;
  }
  size_t count(size_t k) const
  {
    const std::string& f = fields_.at(k);
    if (f.empty() || f.size() > 18 || f.find_first_not_of("0123456789") != std::string::npos)
      fail(k, "is not a non-negative integer");
    return std::stoull(f);
  }
  /** A count of a match's directions: 0 to 4 (three axes, and a second peak). */
  int directions(size_t k) const
  {
    const size_t n = count(k);
    if (n > 4) fail(k, "is more directions than a 2D pose has (at most 4: three axes and a second peak)");
    return static_cast<int>(n);
  }
  const std::string& text(size_t k) const { return fields_.at(k); }
  [[noreturn]] void fail(size_t k, const std::string& problem) const
  {
    throw std::runtime_error("column '" + names_.at(k) + "': '" + fields_.at(k) + "' " + problem);
  }

 private:
  const std::vector<std::string>& names_;
  std::vector<std::string> fields_;
};

tracking::TrackingSource sourceOf(const CsvFields& f, size_t k)
{
  for (const auto s : {tracking::TrackingSource::First, tracking::TrackingSource::Match,
                       tracking::TrackingSource::Searched, tracking::TrackingSource::Odometry,
                       tracking::TrackingSource::ConstantMotion})
    if (f.text(k) == tracking::toString(s)) return s;
  f.fail(k, "is not a tracking source");
}
}  // namespace

std::string formatStatsCsv(const std::vector<ScanStats>& rows)
{
  std::ostringstream out;
  out << kStatsHeader << "\n";
  // mrpt::format has no length limit: "%.6f" or "%.4f" of a value near 1e300 takes over 300
  // characters, and a fixed buffer would cut the line (common/tum_io.cpp meets the same).
  for (const ScanStats& r : rows)
    out << mrpt::format("%zu,%.6f,%s,%zu,%zu,%.6g,%.6g,%.4f,%.4f,%.4f,%.4f,%zu,%d,%zu,%d,%zu,%d,%d\n", r.scan,
                        r.timestamp, toString(r.source), r.valid_rays, r.correspondences, r.match_sq_residuals,
                        r.active_sq_residuals, r.match_ms, r.tracking_ms, r.graph_ms, r.map_ms, r.keyframe,
                        r.new_node ? 1 : 0, r.loops, r.full_optimization ? 1 : 0, r.switched_off, r.ambiguous,
                        r.prior_decided);
  return out.str();
}

std::vector<ScanStats> readStatsCsv(const std::string& path)
{
  std::ifstream in(path);
  if (!in) throw std::runtime_error("stats.csv: cannot open '" + path + "'");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("stats.csv: '" + path + "' line 1: empty file, no header");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line != kStatsHeader && line != olderStatsHeader())
    throw std::runtime_error("stats.csv: '" + path + "' line 1: not the header '" + kStatsHeader + "'");
  std::vector<std::string> names;
  {
    std::stringstream h(line);
    for (std::string n; std::getline(h, n, ',');) names.push_back(n);
  }
  std::vector<ScanStats> rows;
  for (size_t line_no = 2; std::getline(in, line); line_no++)
  {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    try
    {
      const CsvFields f(line, names);
      ScanStats r;
      r.scan = f.count(0);
      r.timestamp = f.number(1);
      r.source = sourceOf(f, 2);
      r.valid_rays = f.count(3);
      r.correspondences = f.count(4);
      r.match_sq_residuals = f.number(5);
      r.active_sq_residuals = f.number(6);
      r.match_ms = f.number(7);
      r.tracking_ms = f.number(8);
      r.graph_ms = f.number(9);
      r.map_ms = f.number(10);
      r.keyframe = f.count(11);
      r.new_node = f.count(12) != 0;
      r.loops = f.count(13);
      r.full_optimization = f.count(14) != 0;
      r.switched_off = f.count(15);
      r.ambiguous = f.directions(16);
      r.prior_decided = names.size() > 17 ? f.directions(17) : 0;
      rows.push_back(r);
    }
    catch (const std::runtime_error& e)
    {
      throw std::runtime_error("stats.csv: '" + path + "' line " + std::to_string(line_no) + ": " + e.what());
    }
  }
  return rows;
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
  if (s.merged_nodes > 0)
  {
    std::snprintf(buf, sizeof(buf), "| Keyframes merged into earlier nodes (revisits) | %zu |\n", s.merged_nodes);
    out << buf;
  }
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
  std::snprintf(buf, sizeof(buf), "| Map memory (grid, sums, nodes' scans) | %.1f MiB |\n",
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
