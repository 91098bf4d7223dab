#include <swslam/app/session.h>

#include <swslam/common/atomic_file.h>
#include <swslam/common/ini_file.h>
#include <swslam/common/tum_io.h>
#include <swslam/graph/io.h>
#include <swslam/io/rawlog_recorder.h>
#include <swslam/io/scan_source.h>
#include <swslam/map/files.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace swslam::app
{
namespace fs = std::filesystem;

namespace
{
/** Stamps within this are the same scan's (keyframes.tum keeps microseconds). */
constexpr double kSameStamp = 1e-5;

std::string stampText(double t)
{
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.6f", t);
  return buf;
}

/** A sibling of `dir` no one else uses: `dir` + suffix + this process's id. */
fs::path sibling(const fs::path& dir, const char* suffix)
{
  return dir.parent_path() / (dir.filename().string() + suffix + std::to_string(::getpid()));
}

void writeSessionFiles(const fs::path& d, const RunRecord& record, const system::RunResults& results,
                       const mrpt::maps::COccupancyGridMap2D& grid,
                       const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& observations)
{
  mrpt::config::CConfigFileMemory ini;
  ini.write("session", "format", kSessionFormat);
  ini.write("session", "nodes", static_cast<uint64_t>(results.graph.nodeCount()));
  ini.write("session", "version", RunRecord::swslamVersion());
  std::string text;
  ini.getContent(text);
  common::writeTextAtomically((d / "session.ini").string(),
                              "# A saved swslam session (doc/sessions.md); swslam --resume continues it.\n" + text);
  common::writeTextAtomically((d / kRunRecordFile).string(), runRecordText(record));
  graph::saveGraph(results.graph, (d / "graph.graph").string(), results.switched_off);
  common::writeTum((d / "keyframes.tum").string(), results.keyframes);
  {
    io::RawlogRecorder nodes((d / "nodes.rawlog").string(), std::chrono::hours(1));
    for (const auto& obs : observations) nodes.write(*obs);
    nodes.flush();
  }
  map::writeGridmap(grid, (d / "map.gridmap.gz").string());
}

}  // namespace

void writeSession(const std::string& dir, const RunRecord& record, const system::RunResults& results,
                  const mrpt::maps::COccupancyGridMap2D& grid,
                  const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& observations)
{
  const size_t n = results.graph.nodeCount();
  if (n == 0) throw std::invalid_argument("session: the run has no graph node to save");
  if (observations.size() != n || results.keyframes.size() != n)
    throw std::invalid_argument("session: " + std::to_string(n) + " graph nodes, " +
                                std::to_string(results.keyframes.size()) + " keyframes and " +
                                std::to_string(observations.size()) + " node observations");
  for (size_t id = 0; id < n; id++)
    if (!observations[id]) throw std::invalid_argument("session: node " + std::to_string(id) + " has no observation");
  const fs::path target = fs::absolute(dir).lexically_normal();
  const fs::path partial = sibling(target, ".partial-"), previous = sibling(target, ".previous-");
  std::error_code ec;
  fs::remove_all(partial, ec);
  try
  {
    fs::create_directories(partial);
    writeSessionFiles(partial, record, results, grid, observations);
  }
  catch (const std::exception& e)
  {
    fs::remove_all(partial, ec);
    throw std::runtime_error(std::string("session: could not write '") + target.string() + "': " + e.what());
  }
  // The previous session moves aside only now, and comes back if the new one cannot take its place.
  const bool had_previous = fs::exists(target);
  if (had_previous) fs::rename(target, previous, ec);
  if (ec)
  {
    fs::remove_all(partial, ec);
    throw std::runtime_error("session: could not replace '" + target.string() + "': " + ec.message());
  }
  fs::rename(partial, target, ec);
  if (ec)
  {
    const std::string why = ec.message();
    if (had_previous) fs::rename(previous, target, ec);
    fs::remove_all(partial, ec);
    throw std::runtime_error("session: could not write '" + target.string() + "': " + why);
  }
  if (had_previous) fs::remove_all(previous, ec);
}

Session readSession(const std::string& dir)
{
  const fs::path d(dir);
  auto path = [&](const char* name) { return (d / name).string(); };
  for (const char* name : {"session.ini", kRunRecordFile, "graph.graph", "keyframes.tum", "nodes.rawlog"})
    if (!fs::is_regular_file(path(name)))
      throw std::invalid_argument("session '" + dir + "': " + name + " is missing (not a folder --save-session wrote?)");
  const auto ini = common::readIniFile(path("session.ini"));
  const size_t format = common::readIniCount(*ini, "session", "format", "session '" + dir + "'");
  if (format < 1 || format > static_cast<size_t>(kSessionFormat))
    throw std::invalid_argument("session '" + dir + "': format " + std::to_string(format) + ", this swslam reads 1 to " +
                                std::to_string(kSessionFormat) + " (saved by swslam " +
                                ini->read_string("session", "version", "?") + ")");
  const size_t nodes = common::readIniCount(*ini, "session", "nodes", "session '" + dir + "'");

  Session s;
  s.record = readRunRecord(path(kRunRecordFile));
  graph::GraphLoadReport load;
  try
  {
    s.resumed.graph = graph::loadGraph(path("graph.graph"), &load);
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("session '" + dir + "': " + e.what());
  }
  if (load.skipped_lines > 0)
    throw std::invalid_argument("session '" + dir + "': graph.graph line " +
                                std::to_string(load.skipped_line_numbers.front()) + ": " + load.skip_reasons.front());
  if (load.placed_vertices > 0 || s.resumed.graph.nodeCount() != nodes)
    throw std::invalid_argument("session '" + dir + "': graph.graph holds " + std::to_string(load.vertices) +
                                " vertices for the " + std::to_string(nodes) + " nodes session.ini states");
  std::vector<common::StampedPose> keyframes;
  try
  {
    keyframes = common::readTum(path("keyframes.tum"));
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("session '" + dir + "': " + e.what());
  }
  if (keyframes.size() != nodes)
    throw std::invalid_argument("session '" + dir + "': keyframes.tum holds " + std::to_string(keyframes.size()) +
                                " poses for " + std::to_string(nodes) + " nodes");
  for (const auto& k : keyframes) s.node_times.push_back(k.t);

  // Every node's observation, in node order, each with its node's stamp.
  try
  {
    auto source = io::openScanSource(path("nodes.rawlog"), io::ScanSourceOptions{false, "", "", ""}, io::CarmenParams());
    sensor::ScanInput in;
    while (source->next(in))
    {
      const size_t id = s.resumed.observations.size();
      if (id >= nodes)
        throw std::invalid_argument("nodes.rawlog holds more than the " + std::to_string(nodes) + " nodes' observations");
      const double t = mrpt::Clock::toDouble(in.observation->timestamp);
      if (!(std::abs(t - s.node_times[id]) <= kSameStamp))
        throw std::invalid_argument("nodes.rawlog's observation " + std::to_string(id) + " is stamped " + stampText(t) +
                                    " s, its node " + stampText(s.node_times[id]) + " s");
      s.resumed.observations.push_back(in.observation);
    }
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("session '" + dir + "': " + e.what());
  }
  if (s.resumed.observations.size() != nodes)
    throw std::invalid_argument("session '" + dir + "': nodes.rawlog holds " +
                                std::to_string(s.resumed.observations.size()) + " observations for " +
                                std::to_string(nodes) + " nodes (cut short?)");
  return s;
}

void visitNodeScans(const std::vector<double>& times, size_t first, const std::string& log,
                    const io::ScanSourceOptions& scans, const io::CarmenParams& carmen, const std::string& what,
                    const std::function<void(size_t, const mrpt::obs::CObservation2DRangeScan::Ptr&)>& visit)
{
  if (first >= times.size()) return;
  io::ScanSourceOptions options = scans;
  options.use_odometry = false;
  auto source = io::openScanSource(log, options, carmen);
  sensor::ScanInput in;
  size_t next = first;
  while (next < times.size() && source->next(in))
  {
    if (std::abs(mrpt::Clock::toDouble(in.observation->timestamp) - times[next]) > kSameStamp) continue;
    visit(next, in.observation);
    next++;
  }
  if (next < times.size())
    throw std::runtime_error(what + ": node " + std::to_string(next) + "'s scan (t = " + stampText(times[next]) +
                             " s) is not in '" + log + "'");
}

std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> nodeObservationsFromLog(const std::vector<double>& times,
                                                                           size_t first, const std::string& log,
                                                                           const RunRecord& how)
{
  std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> out;
  visitNodeScans(times, first, log, io::ScanSourceOptions{false, how.sensor_label, how.scan_topic, how.odom_topic},
                 how.config.carmen, "session",
                 [&](size_t, const mrpt::obs::CObservation2DRangeScan::Ptr& obs) { out.push_back(obs); });
  return out;
}

}  // namespace swslam::app
