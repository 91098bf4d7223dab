#include <swslam/app/bench_localize_run.h>

#include <swslam/app/exit_codes.h>
#include <swslam/app/saved_map.h>
#include <swslam/common/tum_io.h>
#include <swslam/eval/association.h>
#include <swslam/eval/se2_alignment.h>
#include <swslam/geometry/se2_error.h>
#include <swslam/io/scan_source.h>
#include <swslam/localize/localizer.h>
#include <swslam/sensor/scan.h>

#include <mrpt/core/Clock.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <ostream>
#include <random>
#include <stdexcept>

namespace swslam::app
{
namespace
{
using mrpt::poses::CPose2D;
using localize::LocalizationState;

/** A log's scans with the reference pose of each (in the map frame), those without one left out. */
struct ScoredLog
{
  std::vector<sensor::ScanInput> scans;
  std::vector<CPose2D> truth;
  std::vector<double> times;
};

std::vector<sensor::ScanInput> readLog(const std::string& path, bool odometry)
{
  auto source = io::openScanSource(path, {odometry, "", "", ""}, io::CarmenParams());
  std::vector<sensor::ScanInput> out;
  sensor::ScanInput in;
  while (source->next(in))
  {
    sensor::checkObservationGeometry(*in.observation);
    out.push_back(in);
  }
  if (out.empty()) throw std::invalid_argument("'" + path + "' holds no scan");
  return out;
}

/** Reference pose of each scan by stamp (within 1 ms), mapped by `world_to_map`. */
ScoredLog scoredLog(const std::string& path, const std::string& truth_path, bool odometry,
                    const CPose2D& world_to_map)
{
  const auto truth = eval::sortedByTime(common::readTum(truth_path));
  ScoredLog log;
  for (auto& in : readLog(path, odometry))
  {
    const double t = mrpt::Clock::toDouble(in.observation->timestamp);
    const auto k = eval::closestInTime(truth, t, 1e-3);
    if (!k) continue;
    log.scans.push_back(in);
    log.truth.push_back(world_to_map + truth[*k].pose);
    log.times.push_back(t);
  }
  if (log.scans.empty()) throw std::invalid_argument("'" + truth_path + "' has no pose at the stamps of '" + path + "'");
  return log;
}

/** The transform from the world (the map run's reference frame) to the map frame, from the
 * map's nodes and the map run's reference poses at their stamps. */
CPose2D worldToMap(const SavedMap& saved, const std::string& map_truth, double& rms, size_t& paired)
{
  const auto truth = eval::sortedByTime(common::readTum(map_truth));
  std::vector<Eigen::Vector2d> world, map;
  for (size_t id = 0; id < saved.poses.size(); ++id)
  {
    const auto k = eval::closestInTime(truth, mrpt::Clock::toDouble(saved.observations[id]->timestamp), 1e-3);
    if (!k) continue;
    world.emplace_back(truth[*k].pose.x(), truth[*k].pose.y());
    map.emplace_back(saved.poses[id].x(), saved.poses[id].y());
  }
  if (world.size() < 2) throw std::invalid_argument("'" + map_truth + "' has no pose at the map nodes' stamps");
  const CPose2D t = eval::alignSE2(world, map);
  paired = world.size();
  rms = std::sqrt(eval::alignmentCost(t, world, map) / double(world.size()));
  return t;
}

double translationError(const CPose2D& a, const CPose2D& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

double percentile(std::vector<double> v, double q)
{
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * double(v.size())))];
}

struct Timer
{
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double ms() const
  {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
};
/** What each section localizes on. */
struct Bench
{
  const localize::MapNodes& nodes;
  const localize::Relocalizer& relocalizer;
  localize::LocalizerParams params;
  /** A localizer that starts lost. */
  localize::Localizer fresh() const { return localize::Localizer(nodes, relocalizer, params); }
};

/** 1. The whole log from its first scan, no initial pose; its whole-map searches' times to `search_ms`. */
void wholeLog(const Bench& bench, const ScoredLog& log, std::vector<double>& search_ms, std::ostream& out)
{
  localize::Localizer loc = bench.fresh();
  size_t counts[4] = {0, 0, 0, 0};
  std::vector<double> errors, heading_errors, track_ms;
  std::optional<size_t> first;
  for (size_t k = 0; k < log.scans.size(); ++k)
  {
    Timer t;
    const auto r = loc.localize(log.scans[k]);
    const double ms = t.ms();
    counts[static_cast<int>(r.state)]++;
    (r.searched_map ? search_ms : track_ms).push_back(ms);
    if (r.state == LocalizationState::Lost) continue;
    if (!first) first = k;
    errors.push_back(translationError(r.pose, log.truth[k]));
    heading_errors.push_back(std::abs(geometry::wrapAngle(r.pose.phi() - log.truth[k].phi())));
  }
  double sq = 0;
  for (double e : errors) sq += e * e;
  out << "\n1. whole log, from its first scan with no initial pose\n";
  out << "   localized from scan " << (first ? std::to_string(*first) : "never") << "; tracked " << counts[0]
      << ", relocalized " << counts[1] << ", predicted " << counts[2] << ", lost " << counts[3] << "\n";
  if (!errors.empty())
    out << std::setprecision(4) << "   position error: RMS " << std::sqrt(sq / double(errors.size())) << " m, p99 "
        << percentile(errors, 0.99) << " m, max " << percentile(errors, 1.0) << " m; heading max "
        << mrpt::RAD2DEG(percentile(heading_errors, 1.0)) << " deg\n";
  out << std::setprecision(2) << "   time per tracked scan: mean "
      << (track_ms.empty() ? 0.0 : std::accumulate(track_ms.begin(), track_ms.end(), 0.0) / double(track_ms.size()))
      << " ms, p99 " << percentile(track_ms, 0.99) << " ms, max " << percentile(track_ms, 1.0) << " ms\n";
}

/** 2. Random starts: a fresh localizer at a random scan, no initial pose. */
void randomStarts(const Bench& bench, const ScoredLog& log, const BenchLocalizeOptions& o,
                  std::vector<double>& search_ms, std::ostream& out)
{
  std::mt19937 rng(o.seed);
  const double span = o.window + o.follow;
  size_t last_start = 0;
  while (last_start < log.scans.size() && log.times[last_start] - log.times.front() < log.times.back() - log.times.front() - span)
    last_start++;
  if (last_start == 0) throw std::invalid_argument("the log is shorter than --window plus --follow");
  std::uniform_int_distribution<size_t> pick(0, last_start - 1);
  size_t found = 0, succeeded = 0, wrong = 0;
  std::vector<double> delays, errors_at, follow_max;
  for (size_t s = 0; s < o.starts; ++s)
  {
    const size_t start = pick(rng);
    localize::Localizer loc = bench.fresh();
    std::optional<double> at;
    double err_at = 0, worst = 0;
    for (size_t k = start; k < log.scans.size(); ++k)
    {
      const double dt = log.times[k] - log.times[start];
      if (!at && dt > o.window) break;
      if (at && log.times[k] - *at > o.follow) break;
      Timer t;
      const auto r = loc.localize(log.scans[k]);
      if (r.searched_map) search_ms.push_back(t.ms());
      if (r.state == LocalizationState::Lost) continue;
      const double e = translationError(r.pose, log.truth[k]);
      if (!at)
      {
        at = log.times[k];
        err_at = e;
        delays.push_back(dt);
      }
      worst = std::max(worst, e);
    }
    if (!at) continue;
    found++;
    errors_at.push_back(err_at);
    follow_max.push_back(worst);
    if (err_at <= o.max_error) succeeded++;
    if (err_at > 0.5) wrong++;
  }
  out << "\n2. relocalization from " << o.starts << " random starts (seed " << o.seed << "), each within "
      << std::setprecision(1) << o.window << " s of log\n";
  out << "   relocalized " << found << ", within " << std::setprecision(2) << o.max_error << " m: " << succeeded
      << " (" << std::setprecision(0) << 100.0 * double(succeeded) / double(o.starts) << "%); wrong (> 0.5 m): "
      << wrong << "\n";
  out << std::setprecision(3) << "   log time to relocalize: median " << percentile(delays, 0.5) << " s, max "
      << percentile(delays, 1.0) << " s\n";
  out << std::setprecision(4) << "   error at relocalization: median " << percentile(errors_at, 0.5)
      << " m, max " << percentile(errors_at, 1.0) << " m; worst over the next " << std::setprecision(0)
      << o.follow << " s: median " << std::setprecision(4) << percentile(follow_max, 0.5) << " m, max "
      << percentile(follow_max, 1.0) << " m\n";
  out << std::setprecision(0) << "   whole-map search: " << search_ms.size() << " run, median "
      << percentile(search_ms, 0.5) << " ms, max " << percentile(search_ms, 1.0) << " ms\n";
}

/** 3. A log of another place: every scan must stay lost. */
void elsewhere(const Bench& bench, const BenchLocalizeOptions& o, std::ostream& out)
{
  const auto other = readLog(o.elsewhere, o.use_odometry);
  localize::Localizer loc = bench.fresh();
  size_t placed = 0, searched = 0;
  for (const auto& in : other)
  {
    const auto r = loc.localize(in);
    placed += r.state != LocalizationState::Lost;
    searched += r.searched_map;
  }
  out << "\n3. another place: " << o.elsewhere << ", " << other.size() << " scans, " << searched
      << " whole-map searches: localized " << placed << " (lost " << other.size() - placed << ")\n";
}
}  // namespace

int runBenchLocalize(const BenchLocalizeOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-bench-localize", err, [&] {
    const SavedMap saved = readSavedMap(o.map);
    const auto& cfg = saved.record.config;
    double align_rms = 0;
    size_t align_pairs = 0;
    const CPose2D world_to_map = worldToMap(saved, o.map_truth, align_rms, align_pairs);
    const ScoredLog log = scoredLog(o.input, o.truth, o.use_odometry, world_to_map);

    const std::unique_ptr<localize::MapNodes> map_nodes = mapNodesOf(saved, cfg);
    const localize::MapNodes& nodes = *map_nodes;
    Timer build;
    const localize::Relocalizer relocalizer(saved.grid, cfg.system.map.occupied_thresh, cfg.system.map.free_thresh,
                                            cfg.localization);
    const double build_ms = build.ms();
    const localize::LocalizerParams params{cfg.localization, cfg.system.plicp, cfg.system.tracking,
                                           cfg.system.correlative};
    out << std::fixed << std::setprecision(3);
    out << "map: " << o.map << ", " << nodes.size() << " nodes, grid " << saved.grid.getSizeX() << " x "
        << saved.grid.getSizeY() << " cells of " << saved.grid.getResolution() << " m (search grid built in "
        << std::setprecision(0) << build_ms << " ms); map frame to the world on " << align_pairs
        << " nodes, residual RMS " << std::setprecision(4) << align_rms << " m\n";
    out << "log: " << o.input << ", " << log.scans.size() << " scans with a reference pose"
        << (o.use_odometry ? "" : ", laser only") << "\n";

    const Bench bench{nodes, relocalizer, params};
    std::vector<double> search_ms;
    wholeLog(bench, log, search_ms, out);
    if (o.starts > 0) randomStarts(bench, log, o, search_ms, out);
    if (!o.elsewhere.empty()) elsewhere(bench, o, out);
    return kExitOk;
  });
}

}  // namespace swslam::app
