#include "swslam/eval/consistency.h"

#include "swslam/carmen_log.h"
#include "swslam/eval/association.h"
#include "swslam/plicp/plicp.h"
#include "swslam/plicp/run.h"
#include "swslam/system/scan_source.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace swslam::eval
{
using mrpt::poses::CPose2D;

double ConsistencyStats::fractionGood() const
{
  return points ? static_cast<double>(good) / static_cast<double>(points)
                : std::numeric_limits<double>::quiet_NaN();
}

std::vector<std::pair<size_t, size_t>> nearbyPairs(const std::vector<CPose2D>& poses,
                                                   double radius, size_t min_gap)
{
  std::vector<std::pair<size_t, size_t>> pairs;
  const double r2 = radius * radius;
  for (size_t i = 0; i < poses.size(); i++)
    for (size_t j = i + std::max<size_t>(1, min_gap); j < poses.size(); j++)
    {
      const double dx = poses[j].x() - poses[i].x(), dy = poses[j].y() - poses[i].y();
      if (dx * dx + dy * dy <= r2) pairs.emplace_back(i, j);
    }
  return pairs;
}

namespace
{
/** Accumulates errors into the stats of a set of pairs. */
struct Accumulator
{
  ConsistencyStats stats;
  double sum_sq = 0;
  std::vector<double> errors;

  void add(const std::vector<double>& e, const ConsistencyOptions& o)
  {
    stats.pairs++;
    for (const double v : e)
    {
      const double c = std::min(v, o.error_cap);
      sum_sq += c * c;
      if (v < o.good_error) stats.good++;
    }
    stats.points += e.size();
    errors.insert(errors.end(), e.begin(), e.end());
  }

  ConsistencyStats finish()
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    stats.rms_capped = stats.points ? std::sqrt(sum_sq / static_cast<double>(stats.points)) : nan;
    stats.median = nan;
    if (!errors.empty())
    {
      const auto mid = errors.begin() + static_cast<std::ptrdiff_t>(errors.size() / 2);
      std::nth_element(errors.begin(), mid, errors.end());
      stats.median = *mid;
      if (errors.size() % 2 == 0) stats.median = 0.5 * (*mid + *std::max_element(errors.begin(), mid));
    }
    return stats;
  }
};
}  // namespace

ConsistencyResult scanConsistency(const std::vector<Scan>& scans,
                                  const std::vector<CPose2D>& sensor_poses,
                                  const std::vector<std::pair<size_t, size_t>>& pairs,
                                  const ConsistencyOptions& options)
{
  if (scans.size() != sensor_poses.size())
    throw std::invalid_argument("consistency: " + std::to_string(scans.size()) + " scans but " +
                                std::to_string(sensor_poses.size()) + " poses");
  PlicpParams index_params;
  index_params.min_segment_length = options.min_segment;
  Accumulator all, revisits;
  std::unique_ptr<ReferenceScan> reference;  // rebuilt when the pair's first scan changes
  size_t reference_of = std::numeric_limits<size_t>::max();
  std::vector<Eigen::Vector2d> moved;
  std::vector<double> errors;
  for (const auto& [i, j] : pairs)
  {
    if (i >= scans.size() || j >= scans.size())
      throw std::invalid_argument("consistency: pair (" + std::to_string(i) + ", " +
                                  std::to_string(j) + ") past the " +
                                  std::to_string(scans.size()) + " scans");
    if (i != reference_of)
    {
      reference = std::make_unique<ReferenceScan>(scans[i], index_params);
      reference_of = i;
    }
    const CPose2D rel = sensor_poses[j] - sensor_poses[i];  // j's sensor in i's sensor frame
    plicp::transformInto(scans[j], Eigen::Vector3d(rel.x(), rel.y(), rel.phi()), moved);
    const auto found =
        plicp::findCorrespondences(reference->scan, reference->index, moved, options.max_dist);
    plicp::lineErrorsInto(*reference, moved, found, errors);
    all.add(errors, options);
    if (j - i >= options.revisit_gap) revisits.add(errors, options);
  }
  return {all.finish(), revisits.finish()};
}

PosedScans loadPosedScans(const std::string& log_path,
                          const std::vector<std::vector<StampedPose>>& trajectories,
                          double max_dt, size_t stride, double min_range,
                          const CarmenParams& carmen)
{
  if (stride == 0) throw std::runtime_error("consistency: the stride must be at least 1");
  std::vector<std::vector<StampedPose>> sorted;
  for (const auto& t : trajectories) sorted.push_back(sortedByTime(t));
  PosedScans out;
  out.sensor_poses.resize(trajectories.size());
  auto source = openScanSource(log_path, ScanSourceOptions{false, ""}, carmen);
  ScanInput in;
  size_t associated = 0;
  std::vector<CPose2D> poses(trajectories.size());
  while (source->next(in))
  {
    out.log_scans++;
    const double t = mrpt::Clock::toDouble(in.observation->timestamp);
    bool posed = true;
    for (size_t k = 0; k < sorted.size() && posed; k++)
    {
      const auto at = closestInTime(sorted[k], t, max_dt);
      if (at) poses[k] = sorted[k][*at].pose;
      posed = at.has_value();
    }
    if (!posed)
    {
      out.unposed++;
      continue;
    }
    if (associated++ % stride != 0) continue;
    Scan scan = scanFromObservation(*in.observation, min_range);
    for (size_t k = 0; k < poses.size(); k++)
      out.sensor_poses[k].push_back(poses[k] + scan.sensor_pose);
    out.scans.push_back(std::move(scan));
  }
  if (out.scans.size() < 2)
    throw std::runtime_error("consistency: only " + std::to_string(out.scans.size()) + " of the " +
                             std::to_string(out.log_scans) + " scans of '" + log_path +
                             "' have a pose within " + std::to_string(max_dt) +
                             " s in every trajectory (need 2)");
  return out;
}

std::string formatConsistency(const std::string& name, const ConsistencyResult& r,
                              const ConsistencyOptions& options)
{
  std::string s;
  char buf[256];
  const auto put = [&](const char* prefix, const ConsistencyStats& c) {
    std::snprintf(buf, sizeof(buf),
                  "%s_pairs=%zu\n%s_points=%zu\n%s_frac_good=%.6g\n%s_rms_capped_m=%.6g\n"
                  "%s_median_m=%.6g\n",
                  prefix, c.pairs, prefix, c.points, prefix, c.fractionGood(), prefix,
                  c.rms_capped, prefix, c.median);
    s += buf;
  };
  s += "trajectory=" + name + "\n";
  put("all", r.all);
  put("revisit", r.revisits);
  std::snprintf(buf, sizeof(buf),
                "# %s: %zu pairs, median %.1f mm, %.1f%% under %.0f mm; revisits: %zu pairs, "
                "median %.1f mm, %.1f%% under %.0f mm\n",
                name.c_str(), r.all.pairs, 1000 * r.all.median, 100 * r.all.fractionGood(),
                1000 * options.good_error, r.revisits.pairs, 1000 * r.revisits.median,
                100 * r.revisits.fractionGood(), 1000 * options.good_error);
  s += buf;
  return s;
}

std::string consistencyReport(const std::string& log_path, const std::vector<std::string>& names,
                              const std::vector<std::vector<StampedPose>>& trajectories,
                              const ConsistencyOptions& options, double max_dt, size_t stride,
                              double min_range, const CarmenParams& carmen)
{
  if (names.size() != trajectories.size() || trajectories.empty())
    throw std::invalid_argument("consistency: one name per trajectory, at least one");
  const auto posed = loadPosedScans(log_path, trajectories, max_dt, stride, min_range, carmen);
  std::string out = "scans=" + std::to_string(posed.scans.size()) + "\nlog_scans=" +
                    std::to_string(posed.log_scans) + "\nunposed_scans=" +
                    std::to_string(posed.unposed) + "\n";
  // The pairs come from the first trajectory: every trajectory is scored on the same ones.
  const auto pairs = nearbyPairs(posed.sensor_poses[0], options.radius, options.min_gap);
  for (size_t k = 0; k < names.size(); k++)
    out += formatConsistency(names[k], scanConsistency(posed.scans, posed.sensor_poses[k], pairs, options),
                             options);
  return out;
}

}  // namespace swslam::eval
