#include <swslam/io/scan_source.h>

#include <swslam/geometry/se2_scaling.h>
#include <swslam/io/gzip_file.h>
#include <swslam/io/ros2_bag_reader.h>

#include <mrpt/core/format.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <iostream>

namespace swslam::io
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;
using mrpt::poses::CPose2D;

void OdometryIntegrator::addReading(const CPose2D& odometry, mrpt::Clock::time_point t)
{
  const mrpt::Clock::time_point unknown{};
  if (last_reading_ && t != unknown && last_reading_->time != unknown)
  {
    if (t < last_reading_->time) return;  // out of order: the newer reading stands
    if (t == last_reading_->time)
    {
      last_reading_->pose = odometry;  // a correction at the same time: no new interval
      return;
    }
  }
  previous_reading_ = last_reading_;
  last_reading_ = Reading{odometry, t};
}

void OdometryIntegrator::addIncrement(const CPose2D& increment)
{
  accumulated_ = accumulated_ + increment;
  has_actions_ = true;
}

CPose2D OdometryIntegrator::readingAt(mrpt::Clock::time_point t) const
{
  const Reading& last = *last_reading_;
  const mrpt::Clock::time_point unknown{};
  if (!previous_reading_ || t == unknown || last.time == unknown || previous_reading_->time == unknown)
    return last.pose;
  const double interval = mrpt::system::timeDifference(previous_reading_->time, last.time);
  if (!(interval > 0)) return last.pose;
  const double s = std::clamp(mrpt::system::timeDifference(last.time, t) / interval, -1.0, 1.0);
  return last.pose + geometry::scaledMotion(last.pose - previous_reading_->pose, s);
}

std::optional<CPose2D> OdometryIntegrator::takeIncrement(mrpt::Clock::time_point scan_time)
{
  std::optional<CPose2D> inc;
  std::optional<CPose2D> at_scan;
  if (last_reading_) at_scan = readingAt(scan_time);
  if (has_actions_)
    inc = accumulated_;
  else if (at_scan && reading_at_scan_)
    inc = *at_scan - *reading_at_scan_;  // reading_at_scan^-1 (+) at_scan
  reading_at_scan_ = at_scan;
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
  bool take(const mrpt::obs::CObservation::Ptr& obs, sensor::ScanInput& out)
  {
    if (auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(obs))
    {
      if (label_.empty()) label_ = scan->sensorLabel;
      if (scan->sensorLabel != label_)
      {
        stats_.other_labels[scan->sensorLabel]++;
        return false;
      }
      out.observation = scan;
      out.odometry_increment = odometry_.takeIncrement(scan->timestamp);
      if (!opts_.use_odometry) out.odometry_increment.reset();
      stats_.scans++;
      return true;
    }
    if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(obs))
    {
      odometry_.addReading(odo->odometry, odo->timestamp);
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

  bool next(sensor::ScanInput& out) override
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
      : SourceBase(opts), path_(path), reader_(path, carmen), laser_only_(carmen.laser_only)
  {
  }
  bool next(sensor::ScanInput& out) override
  {
    CarmenRecord record;
    while (reader_.next(record))
      if (take(record.observation, out)) return true;
    return false;
  }
  std::string describe() const override
  {
    // The reader shifts a log whose laser stamps are negative to start at 0: say by how much.
    const double shift = reader_.stats().timestamp_offset;
    const std::string shifted =
        shift > 0 ? mrpt::format(", timestamps shifted by +%.6f s (the log's laser stamps are negative)", shift) : "";
    if (!opts_.use_odometry || laser_only_)
      return "CARMEN log " + path_ + " (odometry not used" + shifted + ")";
    switch (reader_.stats().odometry_source)
    {
      case CarmenOdometrySource::OdomLines: return "CARMEN log " + path_ + " (odometry: ODOM lines" + shifted + ")";
      case CarmenOdometrySource::LaserFields:
        return "CARMEN log " + path_ + " (odometry: the laser lines' odom_x odom_y odom_theta; no ODOM lines" +
               shifted + ")";
      case CarmenOdometrySource::None: break;
    }
    return "CARMEN log " + path_ + " (no odometry" + shifted + ")";
  }
  double fractionRead() const override { return reader_.fractionRead(); }

 private:
  std::string path_;
  CarmenLogReader reader_;
  bool laser_only_;
};

/** A ROS 1 or ROS 2 bag (BagReader or Ros2BagReader): the scans of one LaserScan topic (their
 * label) and the odometry of one topic. */
template <class Reader>
class BagSource : public SourceBase
{
 public:
  BagSource(const std::string& path, const ScanSourceOptions& opts)
      : SourceBase(opts), reader_(path, readerOptions(opts))
  {
    label_ = reader_.scanTopic();
  }
  bool next(sensor::ScanInput& out) override
  {
    mrpt::obs::CObservation::Ptr obs;
    while (reader_.next(obs))
      if (take(obs, out)) return true;
    return false;
  }
  std::string describe() const override
  {
    const std::string bag = std::string(Reader::kFormat) + " " + reader_.path();
    if (reader_.scanTopic().empty()) return bag + " (no LaserScan topic)";
    return bag + " (scans " + reader_.scanTopic() + ", sensor pose " +
           reader_.sensorPoseSource() + ", " +
           (reader_.odomTopic().empty() ? std::string(opts_.use_odometry ? "no odometry topic: laser only"
                                                                         : "odometry not used")
                                        : "odometry " + reader_.odomTopic()) +
           ")";
  }
  double fractionRead() const override { return reader_.fractionRead(); }
  std::string noScanReason(const std::string&) const override
  {
    if (stats_.scans > 0) return "";
    if (reader_.scanTopic().empty())
      return std::string("no ") + Reader::kScanType + " topic in it; its topics: " + formatTopics(reader_.topics());
    return "no message on its LaserScan topic " + reader_.scanTopic() + "; its topics: " +
           formatTopics(reader_.topics());
  }

 private:
  static BagReaderOptions readerOptions(const ScanSourceOptions& opts)
  {
    if (!opts.scan_topic.empty() && !opts.sensor_label.empty() && opts.scan_topic != opts.sensor_label)
      throw std::runtime_error("the sensor label of a bag's scans is their topic: --sensor-label '" +
                               opts.sensor_label + "' and --scan-topic '" + opts.scan_topic + "' disagree");
    return {opts.scan_topic.empty() ? opts.sensor_label : opts.scan_topic, opts.odom_topic, opts.use_odometry};
  }

  Reader reader_;
};

}  // namespace

std::string ScanSource::noScanReason(const std::string& sensor_label) const
{
  return io::noScanReason(stats(), sensor_label);
}

size_t ScanSourceStats::otherSensors() const
{
  size_t n = 0;
  for (const auto& [label, count] : other_labels) n += count;
  return n;
}

std::string noScanReason(const ScanSourceStats& stats, const std::string& sensor_label)
{
  if (stats.scans > 0) return "";
  if (!stats.other_labels.empty())
  {
    std::string labels;
    for (const auto& [label, count] : stats.other_labels)
      labels += (labels.empty() ? "" : ", ") + ("'" + label + "' (" + std::to_string(count) + " scans)");
    return "no scan of sensor '" + sensor_label + "'; the log's laser scans are of " + labels;
  }
  return "no laser scan (CObservation2DRangeScan or CARMEN laser line) in it: " + std::to_string(stats.odometry) +
         " odometry readings, " + std::to_string(stats.other_observations) + " other observations";
}

namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

std::unique_ptr<ScanSource> openScanSource(const std::string& path, const ScanSourceOptions& opts,
                                           const CarmenParams& carmen)
{
  requireLogFile(path);  // before isBagFile reads its first bytes
  if (isRos2Bag(path)) return std::make_unique<BagSource<Ros2BagReader>>(path, opts);
  if (isBagFile(path)) return std::make_unique<BagSource<BagReader>>(path, opts);
  if (!opts.scan_topic.empty() || !opts.odom_topic.empty())
    throw std::runtime_error("'" + path + "' is not a ROS bag: scan and odometry topics apply only to bags");
  for (const char* ext : {".log", ".log.gz", ".clf", ".clf.gz"})
    if (endsWith(path, ext)) return std::make_unique<CarmenSource>(path, opts, carmen);
  return std::make_unique<RawlogSource>(path, opts);
}

}  // namespace swslam::io
