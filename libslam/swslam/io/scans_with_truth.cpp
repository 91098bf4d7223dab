#include <swslam/io/scans_with_truth.h>

#include <swslam/io/rawlog_reader.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::io
{
using mrpt::obs::CObservation2DRangeScan;

ScansWithTruth loadScansWithTruth(const std::string& rawlog_path,
                                  const std::vector<common::StampedPose>& truth, double max_dt)
{
  std::vector<CObservation2DRangeScan::Ptr> scans;
  RawlogReader reader(rawlog_path);
  RawlogItem item;
  while (reader.next(item))
  {
    auto s = std::dynamic_pointer_cast<CObservation2DRangeScan>(item.observation);
    if (s && (scans.empty() || s->sensorLabel == scans.front()->sensorLabel)) scans.push_back(s);
  }
  ScansWithTruth out;
  if (scans.size() == truth.size())
  {
    out.scans = std::move(scans);
    for (const auto& t : truth) out.truth.push_back(t.pose);
    return out;
  }
  for (const auto& s : scans)
  {
    const double t = mrpt::Clock::toDouble(s->timestamp);
    const auto it = std::lower_bound(truth.begin(), truth.end(), t,
                                     [](const common::StampedPose& p, double v) { return p.t < v; });
    const common::StampedPose* best = nullptr;
    for (auto c : {it, it == truth.begin() ? it : std::prev(it)})
      if (c != truth.end() && std::abs(c->t - t) <= max_dt && (!best || std::abs(c->t - t) < std::abs(best->t - t)))
        best = &*c;
    if (!best)
    {
      out.skipped_without_truth++;
      continue;
    }
    out.scans.push_back(s);
    out.truth.push_back(best->pose);
  }
  if (out.scans.size() < 2)
    throw std::runtime_error("benchmark: fewer than 2 scans of '" + rawlog_path +
                             "' have a reference pose (scans: " + std::to_string(scans.size()) +
                             ", reference poses: " + std::to_string(truth.size()) + ")");
  return out;
}

}  // namespace swslam::io
