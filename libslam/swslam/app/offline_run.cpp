#include <swslam/app/offline_run.h>

#include <swslam/app/default_config.h>
#include <swslam/app/output_folder.h>
#include <swslam/app/progress_bar.h>
#include <swslam/app/run_outputs.h>
#include <swslam/app/skip_reporter.h>
#include <swslam/app/stop_signal.h>
#include <swslam/eval/report.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/io/scan_source.h>
#include <swslam/io/throttled_scan_source.h>
#include <swslam/system/slam_system.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <malloc.h>
#include <filesystem>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <thread>

namespace swslam::app
{
namespace
{
/** The input broke off after `read` scans. */
struct InputStopped : std::runtime_error
{
  InputStopped(const std::string& what, size_t read) : std::runtime_error(what), read(read) {}
  size_t read;
};

/** Feeds the source's scans to the system until the source ends, a signal arrives, the scan
 * limit is reached or the system stops; returns the scans read. Paced at
 * opts.realtime_factor times the log's rate if set. Throws InputStopped if the input breaks
 * off. */
size_t feedAll(const OfflineRunOptions& opts, io::ScanSource& source, system::SlamSystem& slam,
               const StopSignal& stop, ProgressBar& bar, SkipReporter& skips,
               std::chrono::steady_clock::time_point t0)
{
  size_t read = 0;
  try
  {
    sensor::ScanInput in;
    std::optional<double> first_stamp;
    while (!stop.requested() && (opts.max_scans == 0 || read < opts.max_scans) && source.next(in))
    {
      if (opts.realtime_factor > 0)
      {
        // Pacing, as a live sensor would deliver the scans.
        const double t = mrpt::Clock::toDouble(in.observation->timestamp);
        if (!first_stamp) first_stamp = t;
        const double due = std::max(0.0, (t - *first_stamp) / opts.realtime_factor);
        const auto due_at = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                     std::chrono::duration<double>(std::min(due, 3600.0)));
        // In slices, so that a signal stops a slow replay at once.
        for (auto now = std::chrono::steady_clock::now(); now < due_at && !stop.requested();
             now = std::chrono::steady_clock::now())
          std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(due_at - now, std::chrono::milliseconds(100)));
        if (stop.requested()) break;
      }
      const system::FeedResult r = slam.feed(std::move(in));
      read++;
      if (r.status == system::FeedStatus::Stopped) break;
      // Numbered as in the log: the scans used are its scans 0, N, 2N...
      if (!r.message.empty()) skips.report(r.status, (read - 1) * opts.throttle_scans, r.message);
      if (!bar.due()) continue;  // the status is gathered only when the bar redraws
      const system::SystemStatus st = slam.status();
      bar.update(source.fractionRead(), st.scans,
                 std::to_string(st.nodes) + " nodes " + std::to_string(st.loops) + " loops");
    }
  }
  catch (const std::exception& e)
  {
    throw InputStopped(e.what(), read);
  }
  return read;
}
}  // namespace

int runOffline(const OfflineRunOptions& opts, std::ostream& out, std::ostream& err)
{
  StopSignal stop;
  system::SystemParams params;
  std::unique_ptr<io::ScanSource> source;
  std::vector<common::StampedPose> truth;
  std::optional<OutputFolder> folder;
  try
  {
    if (!(std::isfinite(opts.realtime_factor) && opts.realtime_factor >= 0))
      throw std::invalid_argument("--realtime-factor must be a finite number, at least 0 (0: as fast as possible), got " +
                                  std::to_string(opts.realtime_factor));
    const std::string config = configOrDefault(opts.config);
    if (opts.config.empty()) err << "swslam: configuration " << config << "\n";
    params = system::loadSystemParams(config);
    if (!opts.ground_truth.empty()) truth = eval::readNonEmptyTum(opts.ground_truth);
    source = io::throttleScans(
        io::openScanSource(opts.input, io::ScanSourceOptions{opts.use_odometry, opts.sensor_label, opts.scan_topic, opts.odom_topic},
                           params.carmen),
        opts.throttle_scans);
    folder.emplace(opts.output);
    if (folder->staleRemoved() > 0)
      err << "swslam: removed " << folder->staleRemoved() << " temporary file(s) that a killed run left in "
          << opts.output << "\n";
  }
  catch (const std::exception& e)
  {
    err << "swslam: " << e.what() << "\n";
    return kExitUsage;
  }

  const auto t0 = std::chrono::steady_clock::now();
  auto slam = std::make_unique<system::SlamSystem>(params, opts.deterministic ? system::RunMode::Deterministic : system::RunMode::Threaded);
  ProgressBar bar(stderr, progressStyleFor(stderr, opts.progress), "swslam: ");
  SkipReporter skips(err, params.system.max_printed_warnings, "swslam: ");
  int code = kExitOk;
  size_t read = 0;
  try
  {
    read = feedAll(opts, *source, *slam, stop, bar, skips, t0);
  }
  catch (const InputStopped& e)
  {
    bar.done();
    read = e.read;
    err << "swslam: input stopped after " << read << " scans: " << e.what()
        << "\nswslam: writing the outputs of what was read\n";
    code = kExitInputError;
  }
  // Stopped by a signal, the run ends without the final refinement's matches (they can take
  // long: every pair of nearby nodes); the final optimization still runs.
  slam->finish(!stop.requested());
  bar.done();
  // A log whose clock is not in seconds (microseconds...) or does not run is not a run with a
  // few skips.
  const size_t bad_stamps = skips.count(system::FeedStatus::TimestampOutOfRange) +
                            skips.count(system::FeedStatus::TimestampNotIncreasing);
  if (2 * bad_stamps > read)
  {
    err << "swslam: " << bad_stamps << " of the " << read
        << " scans read were skipped for their timestamps (see above): is the log's clock in seconds, and "
           "increasing? (CARMEN logs: swslam-carmen2rawlog --repair-timestamps)\n";
    if (code == kExitOk) code = kExitInputError;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (stop.requested())
  {
    err << "swslam: stopped by signal " << stop.signal() << " after " << read
        << " scans; writing the outputs (without the final refinement)\n";
    code = kExitInterrupted;
  }
  if (!slam->error().empty())
  {
    err << "swslam: " << slam->error() << "\n";
    if (code == kExitOk) code = kExitModuleError;
  }
  // A run that tracked no scan has nothing to write: say why instead of an empty map.
  if (slam->status().scans == 0 && !stop.requested())
  {
    const std::string why = read == 0 ? source->noScanReason(opts.sensor_label)
                                      : "none of its " + std::to_string(read) + " scans could be used (see above)";
    err << "swslam: " << source->describe() << ": " << (why.empty() ? "no scan was tracked" : why)
        << "; nothing written\n";
    return code == kExitOk ? kExitInputError : code;
  }

  const system::RunResults results = slam->results();
  // Scans without a valid ray (every range NaN, not positive or out of range) are tracked by
  // the prediction and map nothing: a run of only such scans has no map to write.
  const size_t blind = static_cast<size_t>(std::count_if(results.stats.begin(), results.stats.end(),
                                                         [](const system::ScanStats& r) { return r.valid_rays == 0; }));
  if (blind > 0 && blind == results.stats.size() && !stop.requested())
  {
    err << "swslam: " << source->describe() << ": none of its " << blind
        << " scans tracked had a valid ray (every range NaN, not positive or beyond the sensor's range): nothing "
           "to map; nothing written\n";
    return code == kExitOk ? kExitInputError : code;
  }
  if (blind > 0)
    err << "swslam: " << blind << " of the " << results.stats.size()
        << " scans tracked had no valid ray; the prediction placed them and they mapped nothing\n";
  const mrpt::maps::COccupancyGridMap2D grid = slam->mapSnapshot();
  // The modules' memory is not needed for writing: give it back to the system before the
  // off-screen render allocates its own (this keeps the run's peak memory down).
  slam.reset();
  malloc_trim(0);
  system::RunSummary summary;
  try
  {
    summary = summarizeRun(results, wall, truth.empty() ? nullptr : &truth);
  }
  catch (const std::exception& e)
  {
    err << "swslam: ground truth: " << e.what() << "; the outputs are written without ATE and RPE\n";
    summary = summarizeRun(results, wall);
    if (code == kExitOk) code = kExitInputError;
  }
  std::string text = "# swslam on " + source->describe() + " (" +
                     (opts.deterministic ? "deterministic" : "threaded") + ")\n" + system::formatRunSummary(summary);
  OutputFolder::Replaced written;
  try
  {
    written = folder->replaceRun(runOutputFiles(), [&](const std::string& dir) {
      return writeRunOutputs(dir, results, grid, params.map, text, opts.render);
    });
  }
  catch (const std::exception& e)
  {
    err << "swslam: " << e.what() << "\n";
    return kExitOutputError;
  }
  for (const map::OutputProblem& p : written.problems)
    err << "swslam: could not write " << p.file << ": " << p.message << "\n";
  if (written.kept_previous)
    err << "swslam: the previous run's outputs in " << opts.output << " are kept; what this run wrote is in "
        << (std::filesystem::path(opts.output) / OutputFolder::kUnfinished).string() << "/\n";
  if (!written.problems.empty() && code == kExitOk) code = kExitOutputError;
  out << text << "# outputs in " << opts.output << "/ (map.png, " << (opts.render ? "render.png, " : "")
      << "trajectory.tum, stats.csv, summary.md)\n";
  return code;
}

}  // namespace swslam::app
