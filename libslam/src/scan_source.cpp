#include "swslam/system/scan_source.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <iostream>

namespace swslam
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;
using mrpt::poses::CPose2D;

void OdometryIntegrator::addReading(const CPose2D& odometry) { last_reading_ = odometry; }

void OdometryIntegrator::addIncrement(const CPose2D& increment)
{
  accumulated_ = accumulated_ + increment;
  has_actions_ = true;
}

std::optional<CPose2D> OdometryIntegrator::takeIncrement()
{
  std::optional<CPose2D> inc;
  if (has_actions_)
    inc = accumulated_;
  else if (last_reading_ && reading_at_scan_)
    inc = *last_reading_ - *reading_at_scan_;  // reading_at_scan^-1 (+) last_reading
  reading_at_scan_ = last_reading_;
  accumulated_ = CPose2D();
  has_actions_ = false;
  return inc;
}

namespace
{
/** The logic both formats share: sensor selection and odometry. */
class SourceBase : public ScanSource
{
 public:
  explicit SourceBase(const ScanSourceOptions& opts) : opts_(opts), label_(opts.sensor_label) {}
  const ScanSourceStats& stats() const override { return stats_; }

 protected:
  /** Takes one observation; true if it is a scan to return (written to `out`). */
  bool take(const mrpt::obs::CObservation::Ptr& obs, ScanInput& out)
  {
    if (auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(obs))
    {
      if (label_.empty()) label_ = scan->sensorLabel;
      if (scan->sensorLabel != label_)
      {
        stats_.other_sensors++;
        return false;
      }
      out.observation = scan;
      out.odometry_increment = odometry_.takeIncrement();
      if (!opts_.use_odometry) out.odometry_increment.reset();
      stats_.scans++;
      return true;
    }
    if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(obs))
    {
      odometry_.addReading(odo->odometry);
      stats_.odometry++;
      return false;
    }
    stats_.other_observations++;
    return false;
  }

  const ScanSourceOptions opts_;
  std::string label_;
  OdometryIntegrator odometry_;
  ScanSourceStats stats_;
};

class RawlogSource : public SourceBase
{
 public:
  RawlogSource(const std::string& path, const ScanSourceOptions& opts) : SourceBase(opts), reader_(path) {}

  bool next(ScanInput& out) override
  {
    RawlogItem item;
    while (reader_.next(item))
    {
      if (item.odometry_increment)
      {
        odometry_.addIncrement(item.odometry_increment->poseChange->getMeanVal());
        stats_.odometry++;
      }
      else if (take(item.observation, out))
        return true;
    }
    return false;
  }
  std::string describe() const override { return "rawlog " + reader_.path(); }
  double fractionRead() const override { return reader_.fractionRead(); }

 private:
  RawlogReader reader_;
};

class CarmenSource : public SourceBase
{
 public:
  CarmenSource(const std::string& path, const ScanSourceOptions& opts, const CarmenParams& carmen)
      : SourceBase(opts), path_(path), reader_(path, carmen)
  {
  }
  bool next(ScanInput& out) override
  {
    CarmenRecord record;
    while (reader_.next(record))
      if (take(record.observation, out)) return true;
    return false;
  }
  std::string describe() const override { return "CARMEN log " + path_; }
  double fractionRead() const override { return reader_.fractionRead(); }

 private:
  std::string path_;
  CarmenLogReader reader_;
};

bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

std::unique_ptr<ScanSource> openScanSource(const std::string& path, const ScanSourceOptions& opts,
                                           const CarmenParams& carmen)
{
  for (const char* ext : {".log", ".log.gz", ".clf", ".clf.gz"})
    if (endsWith(path, ext)) return std::make_unique<CarmenSource>(path, opts, carmen);
  return std::make_unique<RawlogSource>(path, opts);
}

}  // namespace swslam
