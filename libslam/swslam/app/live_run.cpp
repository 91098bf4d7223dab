#include <swslam/app/live_run.h>

#include <swslam/app/config.h>
#include <swslam/app/default_config.h>
#include <swslam/app/exit_codes.h>
#include <swslam/app/localization_session.h>
#include <swslam/app/output_folder.h>
#include <swslam/app/progress_bar.h>
#include <swslam/app/run_outputs.h>
#include <swslam/app/run_record.h>
#include <swslam/app/saved_map.h>
#include <swslam/app/skip_reporter.h>
#include <swslam/app/stop_signal.h>
#include <swslam/common/ini_file.h>
#include <swslam/io/hokuyo_link.h>
#include <swslam/io/rawlog_recorder.h>
#include <swslam/system/slam_system.h>


#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

namespace swslam::app
{
using namespace std::chrono;

namespace
{
std::string recordingPath(const LiveRunOptions& opts)
{
  return opts.record.empty() ? opts.output + "/recording.rawlog" : opts.record;
}

/** Where a live run's scans go, and what it writes: the SLAM system's map, or a localization
 * on a saved map. */
class Sink
{
 public:
  virtual ~Sink() = default;
  /** One scan, the sensor's `index`-th; a skipped one is reported to `skips`. */
  virtual void feed(const mrpt::obs::CObservation2DRangeScan::Ptr& scan, size_t index, SkipReporter& skips) = 0;
  /** Empty unless a module failed. */
  virtual std::string error() const = 0;
  virtual std::string status(const io::HokuyoLinkStats& link, double elapsed) const = 0;
  /** Writes every output of what it holds now; false if one failed (said on `err`). */
  virtual bool save(double wall, bool final_save, std::ostream& err) = 0;
  /** No more scans. */
  virtual void finish() = 0;
  virtual const std::vector<std::string>& outputFiles() const = 0;
  /** What the final save wrote, for the run's stdout. */
  virtual std::string summary() const = 0;
};

class MappingSink : public Sink
{
 public:
  MappingSink(const Config& config, const LiveRunOptions& opts)
      : params_(config.system),
        opts_(opts),
        slam_(params_, opts.deterministic ? system::RunMode::Deterministic : system::RunMode::Threaded)
  {
  }
  void feed(const mrpt::obs::CObservation2DRangeScan::Ptr& scan, size_t index, SkipReporter& skips) override
  {
    const system::FeedResult r = slam_.feed({scan, std::nullopt});
    if (r.status != system::FeedStatus::Stopped && !r.message.empty()) skips.report(r.status, index, r.message);
  }
  std::string error() const override { return slam_.error(); }
  std::string status(const io::HokuyoLinkStats& link, double elapsed) const override
  {
    const system::SystemStatus st = slam_.status();
    char buf[256];
    std::snprintf(buf, sizeof(buf),
                  "%s %zu scans %.1f scans/s, %zu nodes, %zu loops, last match %s (%zu corr., %zu rays)%s",
                  link.connected ? "LIVE" : "WAITING FOR SENSOR", st.scans, st.scans / std::max(elapsed, 1e-3),
                  st.nodes, st.loops, toString(st.last_match), st.last_correspondences, st.last_valid_rays,
                  st.skipped ? (", " + std::to_string(st.skipped) + " skipped").c_str() : "");
    return buf;
  }
  bool save(double wall, bool final_save, std::ostream& err) override
  {
    const system::RunResults results = slam_.results();
    const std::string text = "# swslam-live\n" + system::formatRunSummary(summarizeRun(results, wall));
    RunRecord record;
    record.program = "swslam-live";
    record.input = std::filesystem::absolute(recordingPath(opts_)).lexically_normal().string();
    record.deterministic = opts_.deterministic;
    record.config.system = params_;
    const auto problems = writeRunOutputs(opts_.output, results, slam_.mapSnapshot(), params_.map, text,
                                          runRecordText(record), opts_.render && final_save);
    for (const auto& p : problems) err << "swslam-live: could not write " << p.file << ": " << p.message << "\n";
    return problems.empty();
  }
  void finish() override { slam_.finish(); }
  const std::vector<std::string>& outputFiles() const override { return files_; }
  std::string summary() const override
  {
    std::ifstream f(opts_.output + "/summary.md");
    std::ostringstream s;
    if (f) s << f.rdbuf();
    return s.str() + outputsLine(opts_.output, opts_.render);
  }

 private:
  system::SystemParams params_;
  const LiveRunOptions& opts_;
  system::SlamSystem slam_;
  const std::vector<std::string> files_ = runOutputFiles();
};

class LocalizationSink : public Sink
{
 public:
  LocalizationSink(const SavedMap& saved, const Config& config, const LiveRunOptions& opts)
      : opts_(opts), session_(saved, opts.localize, config, std::nullopt)
  {
  }
  void feed(const mrpt::obs::CObservation2DRangeScan::Ptr& scan, size_t index, SkipReporter& skips) override
  {
    system::FeedResult refused;
    try
    {
      if (!session_.feed({scan, std::nullopt}, &refused)) skips.report(refused.status, index, refused.message);
    }
    catch (const std::exception& e)
    {
      error_ = "localization failed at scan " + std::to_string(index) + ": " + e.what();
    }
  }
  std::string error() const override { return error_; }
  std::string status(const io::HokuyoLinkStats& link, double elapsed) const override
  {
    char buf[160];
    std::snprintf(buf, sizeof(buf), "%s %zu scans %.1f scans/s, %s", link.connected ? "LIVE" : "WAITING FOR SENSOR",
                  session_.scans(), session_.scans() / std::max(elapsed, 1e-3),
                  localize::toString(session_.lastState()));
    return buf;
  }
  bool save(double, bool, std::ostream& err) override
  {
    const auto problems = session_.write(opts_.output, recordingPath(opts_));
    for (const auto& p : problems) err << "swslam-live: could not write " << p.file << ": " << p.message << "\n";
    return problems.empty();
  }
  void finish() override {}
  const std::vector<std::string>& outputFiles() const override { return LocalizationSession::outputFiles(); }
  std::string summary() const override { return "# swslam-live --localize\n" + session_.summary(recordingPath(opts_)); }

 private:
  const LiveRunOptions& opts_;
  LocalizationSession session_;
  std::string error_;  ///< the localizer's failure: the run stops, its outputs written
};

/** What a live run holds: its configuration, the sensor, the recording and the output folder. */
struct Opened
{
  Config config;
  std::optional<SavedMap> map;  ///< --localize's
  std::unique_ptr<io::HokuyoLink> link;
  std::unique_ptr<io::RawlogRecorder> recorder;
  std::optional<OutputFolder> folder;
  bool started = false;  ///< a scan came: the previous run's outputs are cleared
};

/** When the run is over: a signal, or the duration since t0. */
struct Deadline
{
  const StopSignal& stop;
  double duration;  ///< [s] 0: none
  steady_clock::time_point t0 = steady_clock::now();
  bool over(steady_clock::time_point now) const
  {
    return stop.requested() || (duration > 0 && std::chrono::duration<double>(now - t0).count() >= duration);
  }
};

/** Phase 1: the options, the configuration, the output folder (before the sensor: one that
 * cannot be written fails at once), the sensor and the recording; false (said on `err`) if
 * one of them cannot be used. */
bool open(const LiveRunOptions& opts, const Deadline& deadline, Opened& in, std::ostream& err)
{
  try
  {
    // Checked before the stall timeout becomes whole milliseconds (a cast of a huge or NaN value).
    if (!(opts.stall_timeout > 0 && opts.stall_timeout <= 3600))
      throw std::invalid_argument("--stall-timeout " + std::to_string(opts.stall_timeout) + " must be in (0, 3600] s");
    if (!(opts.save_period >= 0) || !(opts.duration >= 0) || !std::isfinite(opts.save_period) ||
        !std::isfinite(opts.duration))
      throw std::invalid_argument("--save-period and --duration must be finite and >= 0");
    const auto cfg = common::readIniFile(configOrDefault(opts.config));
    const auto sensor_file = opts.sensor_config.empty() ? nullptr : common::readIniFile(opts.sensor_config);
    // One file holding both, or swslam's config plus the sensor's own rawlog-grabber file
    // (whose other sections, e.g. [global], are rawlog-grabber's and not read here).
    in.config = sensor_file ? loadConfig(*cfg) : loadConfig(*cfg, {opts.sensor_section});
    if (!opts.localize.empty())
    {
      in.map.emplace(readSavedMap(opts.localize));
      // The map's own configuration, unless one is given.
      if (opts.config.empty()) in.config = in.map->record.config;
    }
    const mrpt::config::CConfigFileBase& sensor_cfg = sensor_file ? *sensor_file : *cfg;
    in.folder.emplace(opts.output);
    io::HokuyoLinkOptions lo;
    lo.stall_timeout = milliseconds(static_cast<long>(1000 * opts.stall_timeout));
    lo.stop = [&deadline] { return deadline.over(steady_clock::now()); };  // a poll stuck in garbage returns
    in.link = std::make_unique<io::HokuyoLink>(sensor_cfg, opts.sensor_section, lo,
                                               [&err](const std::string& m) { err << "\nswslam-live: " << m << "\n"; });
    // The previous run's outputs (and recording) are replaced from the first scan on
    // (startRecording): a sensor that never answers leaves them as they were.
    return true;
  }
  catch (const std::exception& e)
  {
    err << "swslam-live: " << e.what() << "\n";
    return false;
  }
}

/** At the first scan: the previous run's outputs cleared, and the recording started, which
 * replaces a previous one (a recording that cannot be made is said, and mapping goes on). */
void startRecording(const LiveRunOptions& opts, Opened& in, const Sink& sink, std::ostream& err)
{
  in.started = true;
  in.folder->clearPreviousRun(sink.outputFiles());
  try
  {
    in.recorder = std::make_unique<io::RawlogRecorder>(recordingPath(opts), milliseconds(1000));
  }
  catch (const std::exception& e)
  {
    err << "swslam-live: " << e.what() << "; mapping goes on without recording\n";
  }
}

/** Phase 2: the sensor's scans recorded and fed to the sink until the deadline or a failed
 * module, the outputs saved every save_period and a status line drawn. */
void run(const LiveRunOptions& opts, const Deadline& deadline, Opened& in, Sink& sink, std::ostream& err,
         RunOutcome& outcome)
{
  auto last_save = deadline.t0, last_status = deadline.t0;
  const bool tty = opts.status && isTerminal(stderr);
  // On a terminal a message starts on a new line, below the status line it interrupts.
  SkipReporter skips(err, in.config.system.system.max_printed_warnings, tty ? "\nswslam-live: " : "swslam-live: ");
  while (sink.error().empty())
  {
    const auto now = steady_clock::now();
    const double elapsed = duration<double>(now - deadline.t0).count();
    if (deadline.over(now)) break;
    if (auto scan = in.link->poll())
    {
      if (!in.started) startRecording(opts, in, sink, err);
      try
      {
        if (in.recorder) in.recorder->write(*scan);
      }
      catch (const std::exception& e)
      {
        err << "swslam-live: " << e.what() << "; mapping goes on without recording\n";
        in.recorder.reset();
      }
      sink.feed(scan, in.link->stats().scans - 1, skips);
    }
    // Nothing is saved before the first scan: a sensor that never answers leaves no empty map.
    if (opts.save_period > 0 && now - last_save >= duration<double>(opts.save_period) && in.link->stats().scans > 0)
    {
      if (in.recorder) in.recorder->flush();
      outcome.outputs_failed |= !sink.save(elapsed, false, err);
      last_save = now;
    }
    if (opts.status && now - last_status >= (tty ? milliseconds(250) : milliseconds(10000)))
    {
      const std::string line = sink.status(in.link->stats(), elapsed);
      if (tty)
        std::fprintf(stderr, "\r%s\033[K", line.c_str());
      else
        err << "swslam-live: " << line << "\n";
      last_status = now;
    }
  }
  if (tty) std::fprintf(stderr, "\n");
  if (deadline.stop.requested()) err << "swslam-live: stopped by signal " << deadline.stop.signal() << "; writing the outputs\n";
  if (in.recorder) in.recorder->flush();
}
}  // namespace

int runLive(const LiveRunOptions& opts, std::ostream& out, std::ostream& err)
{
  StopSignal stop;
  std::signal(SIGPIPE, SIG_IGN);  // the driver writes to sockets the sensor may have closed
  Deadline deadline{stop, opts.duration};
  Opened in;
  if (!open(opts, deadline, in, err)) return kExitUsage;
  std::unique_ptr<Sink> sink;
  try
  {
    if (in.map)
      sink = std::make_unique<LocalizationSink>(*in.map, in.config, opts);
    else
      sink = std::make_unique<MappingSink>(in.config, opts);
  }
  catch (const std::exception& e)
  {
    err << "swslam-live: " << e.what() << "\n";
    return kExitUsage;
  }
  deadline.t0 = steady_clock::now();
  RunOutcome outcome;  // a signal or the duration is how a live run ends: not an interruption
  run(opts, deadline, in, *sink, err, outcome);
  // The sensor is let go first: it stops sending while the run finishes.
  const io::HokuyoLinkStats ls = in.link->stats();
  const std::string address = in.link->address(), retries = in.link->retryPolicy();
  in.link.reset();
  sink->finish();
  out << "# swslam-live: " << ls.scans << " scans received and " << (in.recorder ? in.recorder->written() : 0)
      << " recorded; " << ls.connects << " connection(s), " << ls.errors << " driver error(s), " << ls.stalls
      << " stall(s), " << ls.driver_messages << " driver error message(s), " << ls.garbage_bytes
      << " byte(s) of data that was not SCIP 2.0\n";
  if (ls.scans == 0)
  {
    // No map, no trajectory: say so rather than write a set of empty outputs.
    err << "swslam-live: the sensor never answered: not one scan from " << address << " in "
        << static_cast<long>(duration<double>(steady_clock::now() - deadline.t0).count()) << " s ("
        << ls.attempts << " connection attempt(s), " << ls.errors << " failed; " << retries
        << "): is it powered, and at that address?; nothing written\n";
    out << "# nothing written in " << opts.output << "/ (a previous run's outputs are kept)\n";
    return kExitInputError;
  }
  if (!sink->error().empty())
  {
    err << "swslam-live: " << sink->error() << "\n";
    outcome.module_failed = true;
  }
  outcome.outputs_failed |= !sink->save(duration<double>(steady_clock::now() - deadline.t0).count(), true, err);
  out << sink->summary();
  return exitCode(outcome);
}

}  // namespace swslam::app
