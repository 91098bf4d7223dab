#include <swslam/app/regen_map_run.h>

#include <swslam/app/config.h>
#include <swslam/app/default_config.h>
#include <swslam/app/exit_codes.h>
#include <swslam/app/regen_map.h>
#include <swslam/app/run_outputs.h>
#include <swslam/app/run_record.h>
#include <swslam/graph/io.h>
#include <swslam/map/outputs.h>

#include <filesystem>
#include <optional>
#include <ostream>
#include <stdexcept>

namespace swslam::app
{
namespace
{
/** The config's [map], at `resolution` if given (checked as the config's own value is). */
map::MapParams mapParams(const Config& loaded, const std::optional<double>& resolution)
{
  map::MapParams params = loaded.system.map;
  if (!resolution) return params;
  params.resolution = *resolution;
  try
  {
    map::MapParams::table().check(params);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument("--resolution " + std::to_string(*resolution) + ": " + e.what());
  }
  return params;
}

/** The run's graph, keyframes, every-scan trajectory (else the keyframes) and, for the
 * pictures, its stats.csv rows; problems reading them are printed to `err`. */
system::RunResults loadRun(const std::string& dir, std::ostream& err)
{
  system::RunResults run;
  graph::GraphLoadReport load;
  run.graph = graph::loadGraph(dir + "/graph.graph", &load);
  for (size_t k = 0; k < load.skipped_lines; ++k)
    err << "swslam-regen-map: graph.graph line " << load.skipped_line_numbers[k] << " skipped: " << load.skip_reasons[k]
        << "\n";
  run.switched_off = load.switched_off;
  run.keyframes = common::readTum(dir + "/keyframes.tum");
  // The pictures draw the run's every-scan trajectory when it is there, else the keyframes.
  const std::string every_scan = dir + "/trajectory.tum";
  const bool has_every_scan = std::filesystem::is_regular_file(every_scan);
  run.trajectory = has_every_scan ? common::readTum(every_scan) : run.keyframes;
  // ...and mark the scans the prediction placed, from the run's stats.csv (one row per pose).
  std::string stats_problem;
  if (has_every_scan) run.stats = statsForPictures(dir + "/stats.csv", run.trajectory.size(), stats_problem);
  if (!stats_problem.empty())
    err << "swslam-regen-map: " << stats_problem << "; the pictures mark no scan as placed by the prediction\n";
  return run;
}

/** The run's record (run.ini); none if the run has none, which is an error only if the input
 * is left to it. */
std::optional<RunRecord> recordFor(const RegenMapOptions& o)
{
  const std::string path = (std::filesystem::path(o.run) / kRunRecordFile).string();
  if (std::filesystem::exists(path))
  {
    // With the input and config given, the record only names the sensor: a damaged one is not needed.
    if (!o.input.empty() && !o.config.empty())
    {
      try
      {
        return readRunRecord(path);
      }
      catch (const std::invalid_argument&)
      {
        return std::nullopt;
      }
    }
    return readRunRecord(path);
  }
  if (o.input.empty())
    throw std::invalid_argument("no input log: '" + path + "' is missing (a run before run.ini was written); give the log with -i");
  return std::nullopt;
}
}  // namespace

int runRegenMap(const RegenMapOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-regen-map", err, [&] {
    // What the command line leaves out comes from the run's record.
    const std::optional<RunRecord> record = recordFor(o);
    const Config loaded = !o.config.empty() || !record ? loadConfig(configOrDefault(o.config)) : record->config;
    const std::string input = o.input.empty() ? record->input : o.input;
    const map::MapParams params = mapParams(loaded, o.resolution);
    const system::RunResults run = loadRun(o.run, err);
    RegenReport report;
    // The run's sensor and topics, when its record names them and the log is its own.
    io::ScanSourceOptions scans{false, "", "", ""};
    if (record && input == record->input) scans = {false, record->sensor_label, record->scan_topic, record->odom_topic};
    const auto grid = regenerateMap(run.graph, run.keyframes, input, params, loaded.carmen, scans, &report);
    const auto problems = map::writeMapOutputs(o.output, grid, params, overlayOf(run), o.render);
    for (const auto& p : problems) err << "swslam-regen-map: " << p.file << ": " << p.message << "\n";
    out << report.inserted << " of " << report.nodes << " node scans inserted at " << params.resolution
        << " m; map files in " << o.output << "/\n";
    return problems.empty() ? kExitOk : kExitOutputError;
  });
}

}  // namespace swslam::app
