#include <swslam/app/live_run.h>

#include <swslam/app/config.h>
#include <swslam/app/default_config.h>
#include <swslam/app/exit_codes.h>
#include <swslam/app/output_folder.h>
#include <swslam/app/progress_bar.h>
#include <swslam/app/run_outputs.h>
#include <swslam/app/run_record.h>
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
#include <optional>
#include <ostream>

namespace swslam::app
{
using namespace std::chrono;

namespace
{
std::string statusLine(const system::SystemStatus& s, const io::HokuyoLinkStats& link, double rate)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "%s %zu scans %.1f scans/s, %zu nodes, %zu loops, last match %s (%zu corr., %zu rays)%s",
                link.connected ? "LIVE" : "WAITING FOR SENSOR", s.scans, rate, s.nodes, s.loops,
                toString(s.last_match), s.last_correspondences, s.last_valid_rays,
                s.skipped ? (", " + std::to_string(s.skipped) + " skipped").c_str() : "");
  return buf;
}

std::string recordingPath(const LiveRunOptions& opts)
{
  return opts.record.empty() ? opts.output + "/recording.rawlog" : opts.record;
}

/** Writes every output of what the system holds now (it keeps running); false if one failed. */
bool save(const system::SlamSystem& slam, const system::SystemParams& params, const LiveRunOptions& opts,
          double wall, std::ostream& err, bool final_save)
{
  const system::RunResults results = slam.results();
  const std::string text = "# swslam-live\n" + system::formatRunSummary(summarizeRun(results, wall));
  RunRecord record;
  record.program = "swslam-live";
  record.input = std::filesystem::absolute(recordingPath(opts)).lexically_normal().string();
  record.deterministic = opts.deterministic;
  record.config.system = params;
  const auto problems = writeRunOutputs(opts.output, results, slam.mapSnapshot(), params.map, text,
                                        runRecordText(record), opts.render && final_save);
  for (const auto& p : problems) err << "swslam-live: could not write " << p.file << ": " << p.message << "\n";
  return problems.empty();
}
/** What a live run holds: its configuration, the sensor, the recording and the output folder. */
struct Opened
{
  system::SystemParams params;
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
    in.params = (sensor_file ? loadConfig(*cfg) : loadConfig(*cfg, {opts.sensor_section})).system;
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
void startRecording(const LiveRunOptions& opts, Opened& in, std::ostream& err)
{
  in.started = true;
  in.folder->clearPreviousRun(runOutputFiles());
  try
  {
    in.recorder = std::make_unique<io::RawlogRecorder>(recordingPath(opts), milliseconds(1000));
  }
  catch (const std::exception& e)
  {
    err << "swslam-live: " << e.what() << "; mapping goes on without recording\n";
  }
}

/** Phase 2: the sensor's scans recorded and fed to the system until the deadline or a failed
 * module, the outputs saved every save_period and a status line drawn; then the sensor let go
 * (it stops sending while the run finishes) and the system finished. */
void run(const LiveRunOptions& opts, const Deadline& deadline, Opened& in, system::SlamSystem& slam,
         std::ostream& err, RunOutcome& outcome)
{
  auto last_save = deadline.t0, last_status = deadline.t0;
  const bool tty = opts.status && isTerminal(stderr);
  // On a terminal a message starts on a new line, below the status line it interrupts.
  SkipReporter skips(err, in.params.system.max_printed_warnings, tty ? "\nswslam-live: " : "swslam-live: ");
  while (slam.error().empty())
  {
    const auto now = steady_clock::now();
    const double elapsed = duration<double>(now - deadline.t0).count();
    if (deadline.over(now)) break;
    if (auto scan = in.link->poll())
    {
      if (!in.started) startRecording(opts, in, err);
      try
      {
        if (in.recorder) in.recorder->write(*scan);
      }
      catch (const std::exception& e)
      {
        err << "swslam-live: " << e.what() << "; mapping goes on without recording\n";
        in.recorder.reset();
      }
      const system::FeedResult r = slam.feed({scan, std::nullopt});
      if (r.status != system::FeedStatus::Stopped && !r.message.empty())
        skips.report(r.status, in.link->stats().scans - 1, r.message);
    }
    // Nothing is saved before the first scan: a sensor that never answers leaves no empty map.
    if (opts.save_period > 0 && now - last_save >= duration<double>(opts.save_period) && in.link->stats().scans > 0)
    {
      if (in.recorder) in.recorder->flush();
      outcome.outputs_failed |= !save(slam, in.params, opts, elapsed, err, false);
      last_save = now;
    }
    if (opts.status && now - last_status >= (tty ? milliseconds(250) : milliseconds(10000)))
    {
      const system::SystemStatus s = slam.status();
      const std::string line = statusLine(s, in.link->stats(), s.scans / std::max(elapsed, 1e-3));
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
  system::SlamSystem slam(in.params, opts.deterministic ? system::RunMode::Deterministic : system::RunMode::Threaded);
  deadline.t0 = steady_clock::now();
  RunOutcome outcome;  // a signal or the duration is how a live run ends: not an interruption
  run(opts, deadline, in, slam, err, outcome);
  // The sensor is let go first: it stops sending while the run finishes.
  const io::HokuyoLinkStats ls = in.link->stats();
  const std::string address = in.link->address(), retries = in.link->retryPolicy();
  in.link.reset();
  slam.finish();
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
  if (!slam.error().empty())
  {
    err << "swslam-live: " << slam.error() << "\n";
    outcome.module_failed = true;
  }
  outcome.outputs_failed |= !save(slam, in.params, opts, duration<double>(steady_clock::now() - deadline.t0).count(),
                                  err, true);
  std::ifstream summary(opts.output + "/summary.md");
  if (summary) out << summary.rdbuf();
  out << outputsLine(opts.output, opts.render);
  return exitCode(outcome);
}

}  // namespace swslam::app
