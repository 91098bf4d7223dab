#include <swslam/eval/consistency.h>

#include <swslam/eval/association.h>
#include <swslam/io/carmen_log.h>
#include <swslam/io/scan_source.h>
#include <swslam/plicp/plicp.h>
#include <swslam/plicp/run.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
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
  const size_t n = poses.size(), gap = std::max<size_t>(1, min_gap);
  if (gap >= n) return pairs;
  for (size_t i = 0; i + gap < n; i++)
    for (size_t j = i + gap; j < n; j++)
    {
      const double dx = poses[j].x() - poses[i].x(), dy = poses[j].y() - poses[i].y();
      if (dx * dx + dy * dy <= r2) pairs.emplace_back(i, j);
    }
  return pairs;
}

namespace
{
/** Accumulates errors into the stats of a set of pairs. The median comes from a histogram of
 * kHistogramStep bins up to max_dist (every error is below it: a point farther than max_dist
 * from its nearest ray is unmatched), so memory stays constant however many pairs a run has. */
struct Accumulator
{
  static constexpr double kHistogramStep = 1e-4;  ///< [m] resolution of the median
  ConsistencyStats stats;
  double sum_sq = 0;
  std::vector<size_t> bins;

  explicit Accumulator(const ConsistencyOptions& o)
      : bins(static_cast<size_t>(std::ceil(o.max_dist / kHistogramStep)) + 1, 0)
  {
  }

  void add(const std::vector<double>& e, const ConsistencyOptions& o)
  {
    stats.pairs++;
    for (const double v : e)
    {
      const double c = std::min(v, o.error_cap);
      sum_sq += c * c;
      if (v < o.good_error) stats.good++;
      bins[std::min(bins.size() - 1, static_cast<size_t>(v / kHistogramStep))]++;
    }
    stats.points += e.size();
  }

  ConsistencyStats finish()
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    stats.rms_capped = stats.points ? std::sqrt(sum_sq / static_cast<double>(stats.points)) : nan;
    stats.median = nan;
    // The bin holding the middle error (the lower middle one for an even count), at its centre.
    size_t seen = 0;
    for (size_t b = 0; b < bins.size() && stats.points; b++)
    {
      seen += bins[b];
      if (2 * seen > stats.points - 1)
      {
        stats.median = (static_cast<double>(b) + 0.5) * kHistogramStep;
        break;
      }
    }
    return stats;
  }
};
}  // namespace

ConsistencyResult scanConsistency(const std::vector<sensor::Scan>& scans,
                                  const std::vector<CPose2D>& sensor_poses,
                                  const std::vector<std::pair<size_t, size_t>>& pairs,
                                  const ConsistencyOptions& options)
{
  if (scans.size() != sensor_poses.size())
    throw std::invalid_argument("consistency: " + std::to_string(scans.size()) + " scans but " +
                                std::to_string(sensor_poses.size()) + " poses");
  plicp::PlicpParams index_params;
  index_params.min_segment_length = options.min_segment;
  Accumulator all(options), revisits(options);
  std::unique_ptr<plicp::ReferenceScan> reference;  // rebuilt when the pair's first scan changes
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
      reference = std::make_unique<plicp::ReferenceScan>(scans[i], index_params);
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
                          const std::vector<std::vector<common::StampedPose>>& trajectories,
                          double max_dt, size_t stride, double min_range,
                          const io::CarmenParams& carmen, const std::string& sensor_label)
{
  if (stride == 0) throw std::runtime_error("scans at a trajectory's poses: the stride must be at least 1");
  std::vector<std::vector<common::StampedPose>> sorted;
  for (const auto& t : trajectories) sorted.push_back(sortedByTime(t));
  PosedScans out;
  out.sensor_poses.resize(trajectories.size());
  auto source = io::openScanSource(log_path, io::ScanSourceOptions{false, sensor_label, "", ""}, carmen);
  sensor::ScanInput in;
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
    sensor::Scan scan = sensor::scanFromObservation(*in.observation, min_range);
    for (size_t k = 0; k < poses.size(); k++)
      out.sensor_poses[k].push_back(poses[k] + scan.sensor_pose);
    out.scans.push_back(std::move(scan));
  }
  if (out.scans.size() < 2)
  {
    char dt[32];
    std::snprintf(dt, sizeof(dt), "%g", max_dt);
    throw std::runtime_error("scans at a trajectory's poses: " + std::to_string(associated) + " of the " +
                             std::to_string(out.log_scans) + " scans of '" + log_path +
                             "' have a pose within " + dt + " s in every trajectory, " +
                             std::to_string(out.scans.size()) + " kept with stride " +
                             std::to_string(stride) + " (need 2)");
  }
  return out;
}

std::string formatConsistency(const std::string& name, const ConsistencyResult& r,
                              const ConsistencyOptions& options)
{
  std::string s = "trajectory=" + name + "\n";
  char buf[256];
  const auto put = [&](const char* prefix, const ConsistencyStats& c) {
    std::snprintf(buf, sizeof(buf),
                  "%s_pairs=%zu\n%s_points=%zu\n%s_frac_good=%.6g\n%s_rms_capped_m=%.6g\n"
                  "%s_median_m=%.6g\n",
                  prefix, c.pairs, prefix, c.points, prefix, c.fractionGood(), prefix,
                  c.rms_capped, prefix, c.median);
    s += buf;
  };
  put("all", r.all);
  put("revisit", r.revisits);
  const auto human = [&](const ConsistencyStats& c) {
    if (c.points == 0) return std::to_string(c.pairs) + " pairs, no matched point";
    std::snprintf(buf, sizeof(buf), "%zu pairs, median %.1f mm, %.1f%% under %.0f mm", c.pairs,
                  1000 * c.median, 100 * c.fractionGood(), 1000 * options.good_error);
    return std::string(buf);
  };
  s += "# " + name + ": " + human(r.all) + "; revisits: " + human(r.revisits) + "\n";
  return s;
}

std::string consistencyReport(const std::string& log_path, const std::vector<std::string>& names,
                              const std::vector<std::vector<common::StampedPose>>& trajectories,
                              const ConsistencyOptions& options, double max_dt, size_t stride,
                              double min_range, const io::CarmenParams& carmen,
                              const std::string& sensor_label)
{
  if (names.size() != trajectories.size() || trajectories.empty())
    throw std::invalid_argument("consistency: one name per trajectory, at least one");
  const auto posed =
      loadPosedScans(log_path, trajectories, max_dt, stride, min_range, carmen, sensor_label);
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
