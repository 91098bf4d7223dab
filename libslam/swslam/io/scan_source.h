#pragma once
// Where a run's scans come from: an MRPT rawlog (either format), a CARMEN log, a ROS 1 bag or a
// ROS 2 bag (a rosbag2 folder, a .mcap or .db3 file),
// read one scan at a time. Odometry found in the log (CObservationOdometry readings, rawlog
// actions, nav_msgs/Odometry messages) becomes each scan's odometry increment since the
// previous scan, unless disabled.

#include <swslam/io/bag_reader.h>
#include <swslam/io/carmen_log.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/sensor/scan_input.h>

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace swslam::io
{
struct ScanSourceOptions
{
  bool use_odometry = true;
  std::string sensor_label;  ///< only scans of this sensor; empty: the first one seen (bags: the scan topic)
  std::string scan_topic;    ///< bags only: the LaserScan topic; empty: sensor_label, else the only one
  std::string odom_topic;    ///< bags only: the Odometry topic; empty: the only one, if any
};

/** Counts of what a source skipped. */
struct ScanSourceStats
{
  size_t scans = 0;              ///< scans returned
  std::map<std::string, size_t> other_labels;  ///< scans of another sensor label, skipped, by label
  size_t other_observations = 0; ///< observations that are neither scans nor odometry
  size_t odometry = 0;           ///< odometry readings/actions used

  /** Scans of other sensors, skipped. */
  size_t otherSensors() const;
};

class ScanSource
{
 public:
  virtual ~ScanSource() = default;
  /** The next scan; false at the end. Throws RawlogError (rawlogs) or std::runtime_error
   * naming the problem when the input is corrupt: what was returned before stays valid. */
  virtual bool next(sensor::ScanInput& out) = 0;
  virtual const ScanSourceStats& stats() const = 0;
  virtual std::string describe() const = 0;
  /** Fraction of the input read, in [0, 1]. */
  virtual double fractionRead() const = 0;
  /** Why it gave no scan (see the function noScanReason below); empty if it gave scans. */
  virtual std::string noScanReason(const std::string& sensor_label) const;
};

/** Why a source gave no scan: the labels it skipped (when a sensor label was asked for), or
 * that it held no laser scan at all. Empty if it gave scans. */
std::string noScanReason(const ScanSourceStats& stats, const std::string& sensor_label);

/** Opens `path` as a ROS 2 bag if it is one (isRos2Bag: a folder with metadata.yaml, a .mcap
 * or .db3 file), as a ROS 1 bag if it is one (isBagFile), as a CARMEN log if its name ends in
 * .log or .log.gz (or .clf), else as a rawlog. Throws std::runtime_error if it cannot be opened, if
 * it is a pipe, socket or device (a FIFO would block the open), or if topics are given for an
 * input that is not a bag. */
std::unique_ptr<ScanSource> openScanSource(const std::string& path, const ScanSourceOptions& opts,
                                           const CarmenParams& carmen);

/** Turns odometry readings between scans into per-scan increments. Absolute readings are
 * aligned with the scans' times: the odometry at a scan is extrapolated (or interpolated)
 * from the last two readings at their constant velocity, by at most one reading interval, so
 * odometry and scans at different rates give the motion between the scans themselves. */
class OdometryIntegrator
{
 public:
  /** An absolute odometry reading (CObservationOdometry) taken at `t` (default: unknown). A
   * reading older than the last one is ignored; one at the same time replaces it. */
  void addReading(const mrpt::poses::CPose2D& odometry, mrpt::Clock::time_point t = {});
  /** A relative motion (rawlog action). */
  void addIncrement(const mrpt::poses::CPose2D& increment);
  /** The motion since the previous call (nothing if no odometry arrived in between or
   * before the previous scan); starts a new interval. `scan_time` (default: unknown) aligns
   * absolute readings with the scan. */
  std::optional<mrpt::poses::CPose2D> takeIncrement(mrpt::Clock::time_point scan_time = {});

 private:
  /** The odometry at time t from the last readings (the last one if t or their times are
   * unknown). */
  mrpt::poses::CPose2D readingAt(mrpt::Clock::time_point t) const;

  struct Reading
  {
    mrpt::poses::CPose2D pose;
    mrpt::Clock::time_point time;
  };
  std::optional<Reading> last_reading_, previous_reading_;
  std::optional<mrpt::poses::CPose2D> reading_at_scan_;  ///< odometry at the last scan
  mrpt::poses::CPose2D accumulated_;  ///< actions since the last scan
  bool has_actions_ = false;
};

}  // namespace swslam::io
