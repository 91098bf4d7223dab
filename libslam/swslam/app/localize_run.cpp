#include <swslam/app/localize_run.h>

#include <swslam/app/config.h>
#include <swslam/app/exit_codes.h>
#include <swslam/app/localization_session.h>
#include <swslam/app/output_folder.h>
#include <swslam/app/saved_map.h>
#include <swslam/app/stop_signal.h>
#include <swslam/io/scan_source.h>

#include <mrpt/core/bits_math.h>

#include <ostream>

namespace swslam::app
{
int runLocalize(const LocalizeOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-localize", err, [&] {
    const SavedMap saved = readSavedMap(o.map);
    const Config cfg = o.config.empty() ? saved.record.config : loadConfig(o.config);
    auto source = io::openScanSource(o.input, {o.use_odometry, o.sensor_label, o.scan_topic, o.odom_topic}, cfg.carmen);
    OutputFolder folder(o.output);
    std::optional<mrpt::poses::CPose2D> initial;
    if (o.initial_pose)
      initial = mrpt::poses::CPose2D((*o.initial_pose)[0], (*o.initial_pose)[1], mrpt::DEG2RAD((*o.initial_pose)[2]));
    LocalizationSession session(saved, o.map, cfg, initial);

    RunOutcome outcome;
    StopSignal stop;
    bool printed_skip = false;
    try
    {
      sensor::ScanInput in;
      while ((o.max_scans == 0 || session.scans() < o.max_scans) && !stop.requested() && source->next(in))
      {
        system::FeedResult refused;
        const localize::LocalizedScan* placed = nullptr;
        try
        {
          placed = session.feed(in, &refused);
        }
        catch (const std::exception& e)
        {
          err << "swslam-localize: localization failed at scan " << session.scans() << ": " << e.what() << "\n";
          outcome.module_failed = true;
          break;
        }
        if (!placed && !printed_skip)
        {
          err << "swslam-localize: skipped a scan (and any like it; counted in summary.md): " << refused.message << "\n";
          printed_skip = true;
        }
      }
    }
    catch (const std::exception& e)
    {
      err << "swslam-localize: input '" << o.input << "' broke off after " << session.scans() << " scans: " << e.what()
          << "\n";
      outcome.input_failed = true;
    }
    outcome.interrupted = stop.requested();
    if (session.scans() == 0 && !outcome.input_failed)
    {
      const std::string why = source->noScanReason(o.sensor_label);
      err << "swslam-localize: " << o.input << ": no scan to localize" << (why.empty() ? "" : ": " + why) << "\n";
      outcome.nothing_to_map = true;
    }
    const auto written = folder.replaceRun(LocalizationSession::outputFiles(),
                                           [&](const std::string& dir) { return session.write(dir, o.input); });
    for (const auto& p : written.problems) err << "swslam-localize: " << p.file << ": " << p.message << "\n";
    outcome.outputs_failed = !written.problems.empty();
    out << session.summary(o.input);
    if (session.scans() > 0 && !session.anyLocalized())
    {
      err << "swslam-localize: no scan was localized: every scan lost (a log of another place, or a map that does "
             "not cover it)\n";
      outcome.nothing_to_map = true;
    }
    return exitCode(outcome);
  });
}

}  // namespace swslam::app
