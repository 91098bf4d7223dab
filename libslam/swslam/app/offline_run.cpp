#include <swslam/app/offline_run.h>

#include <swslam/app/config.h>
#include <swslam/app/default_config.h>
#include <swslam/app/output_folder.h>
#include <swslam/app/progress_bar.h>
#include <swslam/app/run_outputs.h>
#include <swslam/app/run_record.h>
#include <swslam/app/session.h>
#include <swslam/app/skip_reporter.h>
#include <swslam/app/stop_signal.h>
#include <swslam/eval/report.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/io/scan_source.h>
#include <swslam/io/throttled_scan_source.h>
#include <swslam/map/builder.h>
#include <swslam/map/change_detection.h>
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
/** What a run reads, each opened and checked before any work: the configuration, the input,
 * the ground truth, and the output folder, held for the run. */
struct Opened
{
  Config config;
  std::optional<Session> session;  ///< --resume's
  std::unique_ptr<io::ScanSource> source;
  std::vector<common::StampedPose> truth;
  std::optional<OutputFolder> folder;
};

/** What a run produced, with the system gone (its memory given back before the outputs are
 * written: the off-screen render allocates its own). */
struct Produced
{
  size_t read = 0;     ///< scans read from the input
  size_t tracked = 0;  ///< scans the system tracked
  size_t bad_stamps = 0;  ///< scans skipped for their timestamps
  std::string error;   ///< a module's failure
  double wall = 0;     ///< [s]
  system::RunResults results;
  mrpt::maps::COccupancyGridMap2D grid;
};

/** Phase 1: the configuration, input, ground truth and output folder; false (said on `err`)
 * if one of them cannot be used. */
bool open(const OfflineRunOptions& opts, Opened& in, std::ostream& err)
{
  try
  {
    if (!(std::isfinite(opts.realtime_factor) && opts.realtime_factor >= 0))
      throw std::invalid_argument("--realtime-factor must be a finite number, at least 0 (0: as fast as possible), got " +
                                  std::to_string(opts.realtime_factor));
    if (!opts.resume.empty())
    {
      if (!opts.config.empty())
        throw std::invalid_argument("--resume continues with the session's configuration (its run.ini): -c is not "
                                    "allowed with it");
      in.session = readSession(opts.resume);
      in.config = in.session->record.config;
      err << "swslam: resuming the session in " << opts.resume << " (" << in.session->resumed.graph.nodeCount()
          << " nodes)\n";
    }
    else
    {
      const std::string config = configOrDefault(opts.config);
      if (opts.config.empty()) err << "swslam: configuration " << config << "\n";
      in.config = loadConfig(config);
    }
    if (!opts.ground_truth.empty()) in.truth = eval::readNonEmptyTum(opts.ground_truth);
    in.source = io::throttleScans(
        io::openScanSource(opts.input,
                           io::ScanSourceOptions{opts.use_odometry, opts.sensor_label, opts.scan_topic, opts.odom_topic},
                           in.config.carmen),
        opts.throttle_scans);
    if (!opts.save_session.empty())
    {
      // A session takes its folder's place whole: the run's outputs there would go with it.
      const auto session = std::filesystem::weakly_canonical(std::filesystem::absolute(opts.save_session));
      const auto output = std::filesystem::weakly_canonical(std::filesystem::absolute(opts.output));
      const auto [end, _] = std::mismatch(session.begin(), session.end(), output.begin(), output.end());
      if (end == session.end())
        throw std::invalid_argument("--save-session " + opts.save_session + " holds the output folder " + opts.output +
                                    ": a session replaces its whole folder; save it elsewhere");
    }
    in.folder.emplace(opts.output);
    if (in.folder->staleRemoved() > 0)
      err << "swslam: removed " << in.folder->staleRemoved() << " temporary file(s) that a killed run left in "
          << opts.output << "\n";
    return true;
  }
  catch (const std::exception& e)
  {
    err << "swslam: " << e.what() << "\n";
    return false;
  }
}

/** Phase 2: the input through the system, then the final optimization and, unless a signal
 * stopped the run (it can take long: every pair of nearby nodes), the final refinement. */
Produced run(const OfflineRunOptions& opts, Opened& in, const StopSignal& stop, std::ostream& err, RunOutcome& outcome)
{
  Produced p;
  const auto t0 = std::chrono::steady_clock::now();
  auto slam = std::make_unique<system::SlamSystem>(
      in.config.system, opts.deterministic ? system::RunMode::Deterministic : system::RunMode::Threaded);
  if (in.session)
  {
    slam->resume(in.session->resumed);
    // What is needed of it again is its observations (the change report, a saved session);
    // the graph is the system's now.
    in.session->resumed.graph = graph::PoseGraph();
  }
  ProgressBar bar(stderr, progressStyleFor(stderr, opts.progress), "swslam: ");
  SkipReporter skips(err, in.config.system.system.max_printed_warnings, "swslam: ");
  try
  {
    p.read = feedAll(opts, *in.source, *slam, stop, bar, skips, t0);
  }
  catch (const InputStopped& e)
  {
    bar.done();
    p.read = e.read;
    err << "swslam: input stopped after " << p.read << " scans: " << e.what()
        << "\nswslam: writing the outputs of what was read\n";
    outcome.input_failed = true;
  }
  slam->finish(!stop.requested());
  bar.done();
  p.bad_stamps =
      skips.count(system::FeedStatus::TimestampOutOfRange) + skips.count(system::FeedStatus::TimestampNotIncreasing);
  p.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  p.error = slam->error();
  p.tracked = slam->status().scans;
  p.results = slam->results();
  p.grid = slam->mapSnapshot();
  slam.reset();
  malloc_trim(0);
  return p;
}

/** Phase 3: what the run's outcome says, on `err`; false if there is nothing to write. */
bool diagnose(const OfflineRunOptions& opts, const Opened& in, const Produced& p, const StopSignal& stop,
              std::ostream& err, RunOutcome& outcome)
{
  // A log whose clock is not in seconds (microseconds...) or does not run is not a run with a
  // few skips.
  if (2 * p.bad_stamps > p.read)
  {
    err << "swslam: " << p.bad_stamps << " of the " << p.read
        << " scans read were skipped for their timestamps (see above): is the log's clock in seconds, and "
           "increasing? (CARMEN logs: swslam-carmen2rawlog --repair-timestamps)\n";
    outcome.input_failed = true;
  }
  if (stop.requested())
  {
    err << "swslam: stopped by signal " << stop.signal() << " after " << p.read
        << " scans; writing the outputs (without the final refinement)\n";
    outcome.interrupted = true;
  }
  if (!p.error.empty())
  {
    err << "swslam: " << p.error << "\n";
    outcome.module_failed = true;
  }
  // A run that tracked no scan has nothing to write: say why instead of an empty map.
  if (p.tracked == 0 && !stop.requested())
  {
    const std::string why = p.read > 0             ? "none of its " + std::to_string(p.read) + " scans could be used (see above)"
                            : outcome.input_failed ? "it stopped before its first scan (see above)"
                                                   : in.source->noScanReason(opts.sensor_label);
    err << "swslam: " << in.source->describe() << ": " << (why.empty() ? "no scan was tracked" : why)
        << "; nothing written\n";
    outcome.nothing_to_map = true;
    return false;
  }
  // Scans without a valid ray (every range NaN, not positive or out of range) are tracked by
  // the prediction and map nothing: a run of only such scans has no map to write.
  const auto& stats = p.results.stats;
  const size_t blind = static_cast<size_t>(
      std::count_if(stats.begin(), stats.end(), [](const system::ScanStats& r) { return r.valid_rays == 0; }));
  if (blind > 0 && blind == stats.size() && !stop.requested())
  {
    err << "swslam: " << in.source->describe() << ": none of its " << blind
        << " scans tracked had a valid ray (every range NaN, not positive or beyond the sensor's range): nothing "
           "to map; nothing written\n";
    outcome.nothing_to_map = true;
    return false;
  }
  if (blind > 0)
    err << "swslam: " << blind << " of the " << stats.size()
        << " scans tracked had no valid ray; the prediction placed them and they mapped nothing\n";
  return true;
}

/** --save-session: the run's graph, keyframes and map with every node's observation (a
 * resumed session's from its own folder, the others from this run's input). A run whose
 * module failed is not saved. */
void saveSession(const OfflineRunOptions& opts, const Produced& p, const RunRecord& record,
                 const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& observations, std::ostream& err,
                 RunOutcome& outcome)
{
  if (!p.error.empty())
  {
    err << "swslam: no session saved: a module failed\n";
    outcome.outputs_failed = true;
    return;
  }
  try
  {
    writeSession(opts.save_session, record, p.results, p.grid, observations);
    err << "swslam: session saved in " << opts.save_session << " (" << observations.size() << " nodes)\n";
  }
  catch (const std::exception& e)
  {
    err << "swslam: " << e.what() << "\n";
    outcome.outputs_failed = true;
  }
}

/** Every node's observation: a resumed session's from its folder, the others from this run's
 * input; none (said) if the input does not give them back. */
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> nodeObservations(const OfflineRunOptions& opts, const Opened& in,
                                                                      const Produced& p, const RunRecord& record,
                                                                      std::ostream& err, RunOutcome& outcome)
{
  std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> observations;
  if (in.session) observations = in.session->resumed.observations;
  std::vector<double> times;
  for (const auto& k : p.results.keyframes) times.push_back(k.t);
  try
  {
    const auto added = nodeObservationsFromLog(times, observations.size(), opts.input, record);
    observations.insert(observations.end(), added.begin(), added.end());
    return observations;
  }
  catch (const std::exception& e)
  {
    err << "swslam: " << e.what() << "; no session saved and no change report\n";
    outcome.outputs_failed = true;
    return {};
  }
}

/** A resumed run: what its scans show that the session's did not, and the reverse: the rays
 * of the session's nodes and of this run's, each counted alone at their final poses, compared. */
std::optional<map::ChangeReport> changesSinceSession(const Opened& in, const Produced& p,
                                                    const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& observations)
{
  if (!in.session || observations.size() != p.results.graph.nodeCount()) return std::nullopt;
  const size_t saved = in.session->resumed.observations.size();
  map::SurveyEvidence before(in.config.system.map), after(in.config.system.map);
  for (size_t id = 0; id < observations.size(); id++)
    (id < saved ? before : after).insert(id, *observations[id], p.results.graph.pose(id));
  return map::detectChanges(before, after);
}

/** Phase 4: the summary (Table I, with ATE and RPE against the ground truth) and every output,
 * replacing the folder's previous run as one. */
void write(const OfflineRunOptions& opts, Opened& in, const Produced& p, std::ostream& out, std::ostream& err,
           RunOutcome& outcome)
{
  system::RunSummary summary;
  try
  {
    summary = summarizeRun(p.results, p.wall, in.truth.empty() ? nullptr : &in.truth);
  }
  catch (const std::exception& e)
  {
    err << "swslam: ground truth: " << e.what() << "; the outputs are written without ATE and RPE\n";
    summary = summarizeRun(p.results, p.wall);
    outcome.truth_unusable = true;
  }
  const std::string text = "# swslam on " + in.source->describe() + " (" +
                           (opts.deterministic ? "deterministic" : "threaded") + ")\n" +
                           system::formatRunSummary(summary);
  RunRecord record;
  record.program = "swslam";
  record.input = std::filesystem::absolute(opts.input).lexically_normal().string();
  record.use_odometry = opts.use_odometry;
  record.deterministic = opts.deterministic;
  record.sensor_label = opts.sensor_label;
  record.scan_topic = opts.scan_topic;
  record.odom_topic = opts.odom_topic;
  record.max_scans = opts.max_scans;
  record.throttle_scans = opts.throttle_scans;
  record.config = in.config;
  std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> observations;
  if ((in.session || !opts.save_session.empty()) && p.error.empty())
    observations = nodeObservations(opts, in, p, record, err, outcome);
  if (!opts.save_session.empty() && !observations.empty()) saveSession(opts, p, record, observations, err, outcome);
  const std::optional<map::ChangeReport> changes = changesSinceSession(in, p, observations);
  OutputFolder::Replaced written;
  try
  {
    written = in.folder->replaceRun(runOutputFiles(), [&](const std::string& dir) {
      auto problems = writeRunOutputs(dir, p.results, p.grid, in.config.system.map, text, runRecordText(record), opts.render);
      if (changes) writeChangeOutputs(dir, p.grid, overlayOf(p.results), *changes, problems);
      return problems;
    });
  }
  catch (const std::exception& e)
  {
    err << "swslam: " << e.what() << "\n";
    outcome.outputs_lost = true;
    return;
  }
  for (const map::OutputProblem& problem : written.problems)
    err << "swslam: could not write " << problem.file << ": " << problem.message << "\n";
  if (written.kept_previous)
    err << "swslam: the previous run's outputs in " << opts.output << " are kept; what this run wrote is in "
        << (std::filesystem::path(opts.output) / OutputFolder::kUnfinished).string() << "/\n";
  outcome.outputs_failed = !written.problems.empty();
  if (changes)
    out << "# changes since the session: " << changes->count(map::ChangeKind::Appeared) << " appeared, "
        << changes->count(map::ChangeKind::Disappeared) << " disappeared (changes.md, changes.png)\n";
  out << text
      << outputsLine(written.kept_previous ? (std::filesystem::path(opts.output) / OutputFolder::kUnfinished).string()
                                           : opts.output,
                     opts.render);
}
}  // namespace

int runOffline(const OfflineRunOptions& opts, std::ostream& out, std::ostream& err)
{
  StopSignal stop;
  Opened in;
  if (!open(opts, in, err)) return kExitUsage;
  RunOutcome outcome;
  const Produced produced = run(opts, in, stop, err, outcome);
  if (diagnose(opts, in, produced, stop, err, outcome)) write(opts, in, produced, out, err, outcome);
  return exitCode(outcome);
}

}  // namespace swslam::app
