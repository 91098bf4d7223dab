#include <swslam/app/localization_session.h>

#include <swslam/app/run_outputs.h>
#include <swslam/common/atomic_file.h>
#include <swslam/common/tum_io.h>

#include <mrpt/core/Clock.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace swslam::app
{
namespace
{
using localize::LocalizationState;

std::string describeMap(const SavedMap& saved, const std::string& dir)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << dir << " (" << (saved.session ? "session" : "run folder") << ", "
    << saved.poses.size() << " nodes, grid " << saved.grid.getSizeX() << " x " << saved.grid.getSizeY()
    << " cells of " << saved.grid.getResolution() << " m)";
  return s.str();
}
}  // namespace

LocalizationSession::LocalizationSession(const SavedMap& saved, const std::string& map_dir, const Config& config,
                                         const std::optional<mrpt::poses::CPose2D>& initial_pose)
    : map_line_(describeMap(saved, map_dir)),
      nodes_(mapNodesOf(saved, config)),
      relocalizer_(std::make_unique<localize::Relocalizer>(saved.grid, config.system.map.occupied_thresh,
                                                           config.system.map.free_thresh, config.localization)),
      localizer_(std::make_unique<localize::Localizer>(
          *nodes_, *relocalizer_,
          localize::LocalizerParams{config.localization, config.system.plicp, config.system.tracking,
                                    config.system.correlative})),
      grid_(saved.grid),
      before_(config.system.map),
      after_(config.system.map),
      keyframe_translation_(config.system.tracking.keyframe_translation),
      keyframe_rotation_(config.system.tracking.keyframe_rotation),
      gate_(config.system.system)
{
  if (initial_pose) localizer_->setInitialPose(*initial_pose);
  for (size_t id = 0; id < saved.observations.size(); ++id)
    before_.insert(id, *saved.observations[id], saved.poses[id]);
}

LocalizationSession::~LocalizationSession() = default;

const localize::LocalizedScan* LocalizationSession::feed(sensor::ScanInput in, system::FeedResult* refused)
{
  const system::FeedResult admitted = gate_.admit(in);
  if (!admitted.ok())
  {
    skipped_++;
    if (refused) *refused = admitted;
    return nullptr;
  }
  const auto start = std::chrono::steady_clock::now();
  Row r;
  r.t = mrpt::Clock::toDouble(in.observation->timestamp);
  r.scan = localizer_->localize(in);
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  rows_.push_back(r);
  // A scan the map's match placed counts for the change report, at a keyframe's spacing.
  const auto& l = rows_.back().scan;
  const bool matched = l.state == LocalizationState::Tracked || l.state == LocalizationState::Relocalized;
  if (matched && (!last_counted_ || ((-*last_counted_) + l.pose).norm() > keyframe_translation_ ||
                  std::abs(((-*last_counted_) + l.pose).phi()) > keyframe_rotation_))
  {
    after_.insert(counted_poses_.size(), *in.observation, l.pose);
    counted_poses_.push_back(l.pose);
    last_counted_ = l.pose;
  }
  return &l;
}

map::ChangeReport LocalizationSession::changes() const { return map::detectChanges(before_, after_); }

bool LocalizationSession::anyLocalized() const
{
  return std::any_of(rows_.begin(), rows_.end(), [](const Row& r) { return r.scan.state != LocalizationState::Lost; });
}

LocalizationState LocalizationSession::lastState() const
{
  return rows_.empty() ? LocalizationState::Lost : rows_.back().scan.state;
}

std::string LocalizationSession::summary(const std::string& input) const
{
  size_t counts[4] = {0, 0, 0, 0}, searches = 0, tracks = 0;
  double search_sum = 0, search_max = 0, track_sum = 0, track_max = 0;
  std::optional<size_t> first;
  for (size_t k = 0; k < rows_.size(); ++k)
  {
    const Row& r = rows_[k];
    counts[static_cast<int>(r.scan.state)]++;
    if (r.scan.state != LocalizationState::Lost && !first) first = k;
    if (r.scan.searched_map)
    {
      searches++;
      search_sum += r.ms;
      search_max = std::max(search_max, r.ms);
    }
    else if (r.scan.state != LocalizationState::Lost)
    {
      tracks++;
      track_sum += r.ms;
      track_max = std::max(track_max, r.ms);
    }
  }
  std::ostringstream s;
  s << std::fixed << std::setprecision(2);
  s << "map: " << map_line_ << "\n";
  s << "input: " << input << "\n";
  s << "scans: " << rows_.size() << "; tracked " << counts[0] << ", relocalized " << counts[1] << ", predicted "
    << counts[2] << ", lost " << counts[3] << "\n";
  if (skipped_ > 0)
    s << "skipped: " << skipped_ << " scans the input gate refused (geometry, stamps; doc/system.md, Bad input)\n";
  if (first)
    s << "first localized: scan " << *first << ", " << rows_[*first].t - rows_.front().t << " s after the first\n";
  else
    s << "first localized: never (every scan lost: a log of another place, or a map that does not cover it)\n";
  if (searches > 0)
    s << "whole-map searches: " << searches << ", mean " << search_sum / searches << " ms, max " << search_max
      << " ms\n";
  if (tracks > 0) s << "tracking: mean " << track_sum / tracks << " ms a scan, max " << track_max << " ms\n";
  const map::ChangeReport c = changes();
  s << "changes since the map: " << c.count(map::ChangeKind::Appeared) << " appeared, "
    << c.count(map::ChangeKind::Disappeared) << " disappeared, over " << c.compared_cells
    << " cells both saw (changes.md, changes.png)\n";
  return s.str();
}

const std::vector<std::string>& LocalizationSession::outputFiles()
{
  static const std::vector<std::string> files = {"localization.tum", "localization.csv", "summary.md", kChangeTable,
                                                 kChangePicture};
  return files;
}

std::vector<map::OutputProblem> LocalizationSession::write(const std::string& dir, const std::string& input) const
{
  std::vector<common::StampedPose> poses;
  std::ostringstream csv;
  csv << "time,state,x,y,yaw_deg,sigma_x,sigma_y,sigma_yaw_deg,inlier_fraction,map_score,node,searched_map,"
         "valid_rays,ms\n";
  for (const Row& r : rows_)
  {
    const auto& l = r.scan;
    const bool lost = l.state == LocalizationState::Lost;
    if (!lost) poses.push_back({r.t, l.pose});
    csv << std::fixed << std::setprecision(6) << r.t << "," << localize::toString(l.state) << ",";
    if (lost)
      csv << ",,,,,,";
    else
      csv << l.pose.x() << "," << l.pose.y() << "," << mrpt::RAD2DEG(l.pose.phi()) << ","
          << std::sqrt(l.covariance(0, 0)) << "," << std::sqrt(l.covariance(1, 1)) << ","
          << mrpt::RAD2DEG(std::sqrt(l.covariance(2, 2))) << ",";
    csv << std::setprecision(4) << l.inlier_fraction << "," << l.map_score << ",";
    if (!lost) csv << l.node;
    csv << "," << (l.searched_map ? 1 : 0) << "," << l.valid_rays << "," << std::setprecision(3) << r.ms << "\n";
  }
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
  attempt("localization.csv", [&](const std::string& p) { common::writeTextAtomically(p, csv.str()); });
  attempt("summary.md",
          [&](const std::string& p) { common::writeTextAtomically(p, "# swslam-localize\n\n" + summary(input)); });
  map::Overlay overlay;
  overlay.nodes = counted_poses_;
  for (const auto& p : poses) overlay.trajectory.push_back(p.pose);
  writeChangeOutputs(dir, grid_, overlay, changes(), problems);
  return problems;
}

}  // namespace swslam::app
