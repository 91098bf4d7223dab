#include "swslam/system/live_run.h"

#include "swslam/system/hokuyo_link.h"
#include "swslam/system/offline_run.h"
#include "swslam/system/progress_bar.h"
#include "swslam/system/rawlog_recorder.h"
#include "swslam/system/run_outputs.h"
#include "swslam/system/skip_reporter.h"
#include "swslam/system/slam_system.h"
#include "swslam/system/stop_signal.h"

#include <mrpt/config/CConfigFile.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>

namespace swslam
{
using namespace std::chrono;

namespace
{
std::string statusLine(const SystemStatus& s, const HokuyoLinkStats& link, double rate)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "%s %zu scans %.1f scans/s, %zu nodes, %zu loops, last match %s (%zu corr., %zu rays)%s",
                link.connected ? "LIVE" : "WAITING FOR SENSOR", s.scans, rate, s.nodes, s.loops,
                toString(s.last_match), s.last_correspondences, s.last_valid_rays,
                s.skipped ? (", " + std::to_string(s.skipped) + " skipped").c_str() : "");
  return buf;
}

/** Writes every output of what the system holds now (it keeps running). */
int save(const SlamSystem& slam, const SystemParams& params, const LiveRunOptions& opts,
         double wall, std::ostream& err, bool final_save)
{
  const RunResults results = slam.results();
  const std::string text = "# swslam-live\n" + formatRunSummary(summarizeRun(results, wall));
  const auto problems = writeRunOutputs(opts.output, results, slam.mapSnapshot(), params.map, text,
                                        opts.render && final_save);
  for (const auto& p : problems) err << "swslam-live: could not write " << p.file << ": " << p.message << "\n";
  return problems.empty() ? 0 : kExitOutputError;
}
}  // namespace

int runLive(const LiveRunOptions& opts, std::ostream& out, std::ostream& err)
{
  StopSignal stop;
  std::signal(SIGPIPE, SIG_IGN);  // the driver writes to sockets the sensor may have closed
  SystemParams params;
  std::unique_ptr<HokuyoLink> link;
  std::unique_ptr<RawlogRecorder> recorder;
  try
  {
    // Checked before the stall timeout becomes whole milliseconds (a cast of a huge or NaN value).
    if (!(opts.stall_timeout > 0 && opts.stall_timeout <= 3600))
      throw std::invalid_argument("--stall-timeout " + std::to_string(opts.stall_timeout) + " must be in (0, 3600] s");
    if (!(opts.save_period >= 0) || !(opts.duration >= 0) || !std::isfinite(opts.save_period) ||
        !std::isfinite(opts.duration))
      throw std::invalid_argument("--save-period and --duration must be finite and >= 0");
    for (const std::string& f : {opts.config, opts.sensor_config})
      if (!f.empty() && !std::filesystem::is_regular_file(f))
        throw std::invalid_argument("config: cannot read '" + f + "'");
    mrpt::config::CConfigFile cfg(opts.config);
    // One file holding both, or swslam's config plus the sensor's own rawlog-grabber file
    // (whose other sections, e.g. [global], are rawlog-grabber's and not read here).
    params = opts.sensor_config.empty() ? loadSystemParams(cfg, {opts.sensor_section}) : loadSystemParams(cfg);
    mrpt::config::CConfigFile sensor_cfg(opts.sensor_config.empty() ? opts.config : opts.sensor_config);
    HokuyoLinkOptions lo;
    lo.stall_timeout = milliseconds(static_cast<long>(1000 * opts.stall_timeout));
    link = std::make_unique<HokuyoLink>(sensor_cfg, opts.sensor_section, lo,
                                        [&err](const std::string& m) { err << "\nswslam-live: " << m << "\n"; });
    std::filesystem::create_directories(opts.output);
    recorder = std::make_unique<RawlogRecorder>(
        opts.record.empty() ? opts.output + "/recording.rawlog" : opts.record, milliseconds(1000));
  }
  catch (const std::exception& e)
  {
    err << "swslam-live: " << e.what() << "\n";
    return kExitUsage;
  }

  SlamSystem slam(params, opts.deterministic ? RunMode::Deterministic : RunMode::Threaded);
  const auto t0 = steady_clock::now();
  auto last_save = t0, last_status = t0;
  const bool tty = opts.status && isTerminal(stderr);
  // On a terminal a message starts on a new line, below the status line it interrupts.
  SkipReporter skips(err, params.system.max_printed_warnings, tty ? "\nswslam-live: " : "swslam-live: ");
  int code = 0;
  while (!stop.requested() && slam.error().empty())
  {
    const auto now = steady_clock::now();
    const double elapsed = duration<double>(now - t0).count();
    if (opts.duration > 0 && elapsed >= opts.duration) break;
    if (auto scan = link->poll())
    {
      try
      {
        recorder->write(*scan);
      }
      catch (const std::exception& e)
      {
        err << "swslam-live: " << e.what() << "; mapping goes on without recording\n";
        recorder.reset();
      }
      const FeedResult r = slam.feed({scan, std::nullopt});
      if (r.status != FeedStatus::Stopped && !r.message.empty())
        skips.report(r.status, link->stats().scans - 1, r.message);
    }
    if (opts.save_period > 0 && now - last_save >= duration<double>(opts.save_period))
    {
      if (recorder) recorder->flush();
      code = std::max(code, save(slam, params, opts, elapsed, err, false));
      last_save = now;
    }
    if (opts.status && now - last_status >= (tty ? milliseconds(250) : milliseconds(10000)))
    {
      const SystemStatus s = slam.status();
      const std::string line = statusLine(s, link->stats(), s.scans / std::max(elapsed, 1e-3));
      if (tty)
        std::fprintf(stderr, "\r%s\033[K", line.c_str());
      else
        err << "swslam-live: " << line << "\n";
      last_status = now;
    }
  }
  if (tty) std::fprintf(stderr, "\n");
  if (stop.requested()) err << "swslam-live: stopped by signal " << stop.signal() << "; writing the outputs\n";
  if (recorder) recorder->flush();
  slam.finish();
  if (!slam.error().empty())
  {
    err << "swslam-live: " << slam.error() << "\n";
    code = kExitModuleError;
  }
  const double wall = duration<double>(steady_clock::now() - t0).count();
  code = std::max(code, save(slam, params, opts, wall, err, true));
  const HokuyoLinkStats& ls = link->stats();
  out << "# swslam-live: " << ls.scans << " scans received and " << (recorder ? recorder->written() : 0)
      << " recorded; " << ls.connects << " connection(s), " << ls.errors << " driver error(s), "
      << ls.stalls << " stall(s), " << ls.driver_messages << " driver error message(s)\n";
  std::ifstream summary(opts.output + "/summary.md");
  out << summary.rdbuf() << "# outputs in " << opts.output << "/\n";
  return code;
}

}  // namespace swslam
