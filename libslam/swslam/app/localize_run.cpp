#include <swslam/app/localize_run.h>

#include <swslam/app/config.h>
#include <swslam/app/default_config.h>
#include <swslam/app/exit_codes.h>
#include <swslam/app/output_folder.h>
#include <swslam/app/saved_map.h>
#include <swslam/app/stop_signal.h>
#include <swslam/common/atomic_file.h>
#include <swslam/common/tum_io.h>
#include <swslam/io/scan_source.h>
#include <swslam/localize/localizer.h>
#include <swslam/sensor/scan.h>

#include <mrpt/core/Clock.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace swslam::app
{
namespace
{
const std::vector<std::string>& outputFiles()
{
  static const std::vector<std::string> files = {"localization.tum", "localization.csv", "summary.md"};
  return files;
}

struct Row
{
  double t = 0;
  localize::LocalizedScan scan;
  double ms = 0;  ///< processing time
};

struct Tally
{
  size_t scans = 0, tracked = 0, relocalized = 0, predicted = 0, lost = 0, searches = 0;
  size_t skipped_geometry = 0;  ///< observations whose geometry failed the input check
  std::optional<size_t> first_localized;
  double search_ms_sum = 0, search_ms_max = 0, track_ms_sum = 0, track_ms_max = 0;
  size_t track_count = 0;
};

Tally tally(const std::vector<Row>& rows, size_t skipped)
{
  Tally t;
  t.skipped_geometry = skipped;
  t.scans = rows.size();
  for (size_t k = 0; k < rows.size(); ++k)
  {
    const auto& r = rows[k];
    switch (r.scan.state)
    {
      case localize::LocalizationState::Tracked: t.tracked++; break;
      case localize::LocalizationState::Relocalized: t.relocalized++; break;
      case localize::LocalizationState::Predicted: t.predicted++; break;
      case localize::LocalizationState::Lost: t.lost++; break;
    }
    if (r.scan.state != localize::LocalizationState::Lost && !t.first_localized) t.first_localized = k;
    if (r.scan.searched_map)
    {
      t.searches++;
      t.search_ms_sum += r.ms;
      t.search_ms_max = std::max(t.search_ms_max, r.ms);
    }
    else if (r.scan.state != localize::LocalizationState::Lost)
    {
      t.track_count++;
      t.track_ms_sum += r.ms;
      t.track_ms_max = std::max(t.track_ms_max, r.ms);
    }
  }
  return t;
}

std::string summaryText(const LocalizeOptions& o, const SavedMap& saved, const std::vector<Row>& rows,
                        const Tally& t)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(2);
  s << "map: " << o.map << " (" << (saved.session ? "session" : "run folder") << ", " << saved.poses.size()
    << " nodes, grid " << saved.grid.getSizeX() << " x " << saved.grid.getSizeY() << " cells of "
    << saved.grid.getResolution() << " m)\n";
  s << "input: " << o.input << "\n";
  s << "scans: " << t.scans << "; tracked " << t.tracked << ", relocalized " << t.relocalized << ", predicted "
    << t.predicted << ", lost " << t.lost << "\n";
  if (t.skipped_geometry > 0)
    s << "skipped: " << t.skipped_geometry << " observations whose geometry failed the input check\n";
  if (t.first_localized)
    s << "first localized: scan " << *t.first_localized << ", " << rows[*t.first_localized].t - rows.front().t
      << " s after the first\n";
  else
    s << "first localized: never (every scan lost: a log of another place, or a map that does not cover it)\n";
  if (t.searches > 0)
    s << "whole-map searches: " << t.searches << ", mean " << t.search_ms_sum / t.searches << " ms, max "
      << t.search_ms_max << " ms\n";
  if (t.track_count > 0)
    s << "tracking: mean " << t.track_ms_sum / t.track_count << " ms a scan, max " << t.track_ms_max << " ms\n";
  return s.str();
}

std::string csvText(const std::vector<Row>& rows)
{
  std::ostringstream s;
  s << "time,state,x,y,yaw_deg,sigma_x,sigma_y,sigma_yaw_deg,inlier_fraction,map_score,node,searched_map,"
       "valid_rays,ms\n";
  s << std::setprecision(9);
  for (const Row& r : rows)
  {
    const auto& l = r.scan;
    const bool lost = l.state == localize::LocalizationState::Lost;
    s << std::fixed << std::setprecision(6) << r.t << "," << localize::toString(l.state) << ",";
    if (lost)
      s << ",,,,,,";
    else
      s << l.pose.x() << "," << l.pose.y() << "," << mrpt::RAD2DEG(l.pose.phi()) << ","
        << std::sqrt(l.covariance(0, 0)) << "," << std::sqrt(l.covariance(1, 1)) << ","
        << mrpt::RAD2DEG(std::sqrt(l.covariance(2, 2))) << ",";
    s << std::setprecision(4) << l.inlier_fraction << "," << l.map_score << ",";
    if (!lost) s << l.node;
    s << "," << (l.searched_map ? 1 : 0) << "," << l.valid_rays << "," << std::setprecision(3) << r.ms << "\n";
  }
  return s.str();
}

localize::MapNodes mapNodes(const SavedMap& saved, const Config& cfg)
{
  std::vector<sensor::Scan> scans;
  scans.reserve(saved.observations.size());
  for (size_t id = 0; id < saved.observations.size(); ++id)
  {
    try
    {
      scans.push_back(sensor::scanFromObservation(*saved.observations[id], cfg.system.tracking.min_range));
    }
    catch (const std::exception& e)
    {
      throw std::invalid_argument("map node " + std::to_string(id) + "'s scan: " + e.what());
    }
  }
  return localize::MapNodes(saved.poses, std::move(scans), cfg.system.plicp);
}
}  // namespace

int runLocalize(const LocalizeOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-localize", err, [&] {
    const SavedMap saved = readSavedMap(o.map);
    const Config cfg = o.config.empty() ? saved.record.config : loadConfig(o.config);
    auto source = io::openScanSource(o.input, {o.use_odometry, o.sensor_label, o.scan_topic, o.odom_topic}, cfg.carmen);
    OutputFolder folder(o.output);

    const localize::MapNodes nodes = mapNodes(saved, cfg);
    const localize::Relocalizer relocalizer(saved.grid, cfg.system.map.occupied_thresh, cfg.system.map.free_thresh,
                                            cfg.localization);
    localize::Localizer localizer(nodes, relocalizer,
                                  {cfg.localization, cfg.system.plicp, cfg.system.tracking, cfg.system.correlative});
    if (o.initial_pose)
      localizer.setInitialPose(
          mrpt::poses::CPose2D((*o.initial_pose)[0], (*o.initial_pose)[1], mrpt::DEG2RAD((*o.initial_pose)[2])));

    RunOutcome outcome;
    std::vector<Row> rows;
    size_t skipped = 0;
    StopSignal stop;
    try
    {
      sensor::ScanInput in;
      while ((o.max_scans == 0 || rows.size() < o.max_scans) && !stop.requested() && source->next(in))
      {
        try
        {
          sensor::checkObservationGeometry(*in.observation);
        }
        catch (const std::invalid_argument& e)
        {
          if (skipped++ == 0) err << "swslam-localize: skipped a scan (and any like it): " << e.what() << "\n";
          continue;
        }
        const auto start = std::chrono::steady_clock::now();
        Row r;
        r.t = mrpt::Clock::toDouble(in.observation->timestamp);
        r.scan = localizer.localize(in);
        r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        rows.push_back(r);
      }
    }
    catch (const std::exception& e)
    {
      err << "swslam-localize: input '" << o.input << "' broke off after " << rows.size() << " scans: " << e.what()
          << "\n";
      outcome.input_failed = true;
    }
    outcome.interrupted = stop.requested();
    if (rows.empty() && !outcome.input_failed)
    {
      err << "swslam-localize: " << o.input << ": no scan to localize"
          << (source->noScanReason(o.sensor_label).empty() ? "" : ": " + source->noScanReason(o.sensor_label)) << "\n";
      outcome.nothing_to_map = true;
    }

    const Tally t = tally(rows, skipped);
    const std::string summary = summaryText(o, saved, rows, t);
    std::vector<common::StampedPose> poses;
    for (const Row& r : rows)
      if (r.scan.state != localize::LocalizationState::Lost) poses.push_back({r.t, r.scan.pose});
    const auto written = folder.replaceRun(outputFiles(), [&](const std::string& dir) {
      std::vector<map::OutputProblem> problems;
      auto attempt = [&](const std::string& name, const std::function<void(const std::string&)>& write) {
        try
        {
          write(dir + "/" + name);
        }
        catch (const std::exception& e)
        {
          problems.push_back({name, e.what()});
        }
      };
      attempt("localization.tum", [&](const std::string& p) { common::writeTum(p, poses); });
      attempt("localization.csv", [&](const std::string& p) { common::writeTextAtomically(p, csvText(rows)); });
      attempt("summary.md", [&](const std::string& p) {
        common::writeTextAtomically(p, "# swslam-localize\n\n" + summary);
      });
      return problems;
    });
    for (const auto& p : written.problems) err << "swslam-localize: " << p.file << ": " << p.message << "\n";
    outcome.outputs_failed = !written.problems.empty();
    out << summary;
    if (!rows.empty() && !t.first_localized)
    {
      err << "swslam-localize: no scan was localized: every scan lost (a log of another place, or a map that does "
             "not cover it)\n";
      outcome.nothing_to_map = true;
    }
    return exitCode(outcome);
  });
}

}  // namespace swslam::app
