#pragma once
// Streaming conversion of CARMEN logs (plain or gzip) into MRPT observations:
// CObservation2DRangeScan for FLASER, RLASER, ROBOTLASER1/2, RAWLASER1..4 and
// CObservationOdometry for ODOM, each with its line's own timestamp. A log without ODOM lines
// (a raw log: Freiburg's .clf) has its odometry in the FLASER/RLASER odom_x odom_y odom_theta
// fields instead: each becomes a CObservationOdometry at its scan's timestamp, just before
// the scan. PARAM lines set the laser offsets, FOV and maximum range. Rules (max range, FOV,
// timestamps, odometry): doc/carmen.md.

#include <swslam/io/gzip_file.h>
#include <swslam/io/read_progress.h>
#include <swslam/io/carmen_line.h>
#include <swslam/io/carmen_params.h>
#include <swslam/io/carmen_rules.h>
#include <swslam/io/carmen_scan.h>

#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace swslam::io
{
/** Per-laser figures of a conversion. */
struct CarmenSensorStats
{
  size_t scans = 0, rays = 0, invalid_rays = 0;
  size_t min_beams = 0, max_beams = 0;
  double aperture = 0, max_range = 0;  ///< of the last scan
  std::string max_range_source;
};

/** Where a log's odometry is: its ODOM lines, else the odometry fields of its laser lines. */
enum class CarmenOdometrySource
{
  None,        ///< neither
  OdomLines,   ///< ODOM lines (the laser lines' odometry fields are not used)
  LaserFields  ///< no ODOM line: FLASER/RLASER odom_x odom_y odom_theta
};

struct CarmenStats
{
  size_t lines = 0, params = 0;
  /** Odometry readings converted, and dropped (CarmenParams::laser_only), from `odometry_source`. */
  size_t odometry = 0, odometry_dropped = 0;
  CarmenOdometrySource odometry_source = CarmenOdometrySource::None;
  size_t malformed = 0, first_malformed_line = 0;
  std::map<std::string, size_t> unknown_messages;      ///< message type -> lines skipped
  std::map<std::string, CarmenSensorStats> lasers;     ///< by label (FLASER...)
  /** Timestamp problems of one stream (a laser label, or "ODOM"). */
  struct Stamps
  {
    size_t count = 0, non_increasing = 0, forward_jumps = 0, repaired = 0;
    size_t negative = 0;       ///< still negative after timestamp_offset: written as 0
    /** Of size beyond the year 2200 in seconds (common/unix_time.h): the line is skipped. */
    size_t out_of_range = 0;
    double repair_period = 0;  ///< [s] used when repairing
  };
  std::map<std::string, Stamps> timestamps;  ///< by stream
  bool repairing = false;
  /** [s] added to every timestamp of the log: -(earliest laser timestamp) if that is
   * negative, since MRPT cannot represent times before 1970 (Clock::toDouble wraps); else 0.
   * Other streams' timestamps still negative after it are written as 0 (and counted). */
  double timestamp_offset = 0;
  size_t timestampProblems() const;
  size_t geometry_warnings = 0;
  size_t saturation_glitches = 0;  ///< readings above a laser's saturation pile (no return)
  size_t scans() const;
  /** Why the reading stopped before the end of the file (its gzip stream is cut short or
   * corrupt), naming the line it reached; empty if the file was read to its end. */
  std::string damage;
};

/** One converted line. */
struct CarmenRecord
{
  mrpt::obs::CObservation::Ptr observation;  ///< CObservation2DRangeScan or CObservationOdometry
  std::optional<mrpt::poses::CPose2D> reference_pose;  ///< laser lines with x y theta
  double timestamp = 0;      ///< [s] as written into the observation (offset, repaired)
  double raw_timestamp = 0;  ///< [s] as logged
  size_t line = 0;           ///< 1-based line number in the log
};

/** Reads a CARMEN log one line at a time. The constructor makes a first pass over the
 * file (saturation values and timestamp periods, without keeping the data); next() then
 * streams the conversion. Warnings go to `warn` (default: stderr), the first
 * params.max_printed_warnings of each kind; stats() counts all of them. A line whose timestamp
 * is beyond +-2200-01-01 in seconds (common/unix_time.h) is skipped and counted; if most are,
 * the constructor refuses the log (std::runtime_error), as it does a log in UTF-16 or UTF-32
 * (text_encoding.h) and one whose PARAM lines mount a laser beyond the bound of
 * sensor/input_bounds.h. A ROBOTLASER line whose two poses do is malformed (skipped, counted). */
class CarmenLogReader
{
 public:
  using WarningSink = std::function<void(const std::string&)>;
  CarmenLogReader(const std::string& path, const CarmenParams& params, WarningSink warn = {});

  /** Next converted observation; false at the end of the file. Throws GzipError naming the
   * file and the last line read if its gzip stream is cut short or corrupt (the records
   * returned before are the file's lines up to there). */
  bool next(CarmenRecord& record);
  const CarmenStats& stats() const { return stats_; }
  /** Fraction of the file read so far, in [0, 1] (for progress and ETA). */
  double fractionRead() const;

 private:
  struct Prescan;  ///< what the first pass gathers
  void prescan();
  /** The file's first 4 KiB: a log in UTF-16 or UTF-32 is refused by name. */
  void checkHead();
  void prescanLine(const CarmenLine& line, Prescan& p);
  /** Each laser's saturation value; readings above it are counted and warned about. */
  void reportSaturation(const Prescan& p);
  /** Refuses a log whose timestamps are mostly out of range. */
  void checkStampsInRange(const Prescan& p) const;
  /** The offset that starts the lasers' stamps at 0, and each stream's repair period. */
  void setTimestampRepair(const Prescan& p);
  void open();
  bool nextLine(std::string& line);
  void warn(size_t& printed, const std::string& msg);
  void addParam(const std::string& name, const std::string& value);
  double stampOf(const std::string& stream, double raw, size_t line);
  /** A logged stamp of size below 2200-01-01 in seconds (a negative one is shifted later). */
  static bool stampInRange(double raw);
  /** True if the line's stamp is in range; else counts and reports the skipped line. */
  bool keepStamp(const std::string& stream, double raw);
  void convertLaser(const CarmenLaser& laser, CarmenRecord& record);
  /** The odometry reading of `scan`'s laser line, at the scan's timestamp. */
  CarmenRecord laserOdometry(const CarmenLaser& laser, const CarmenRecord& scan);

  std::string path_;
  CarmenParams params_;
  WarningSink warn_;
  std::unique_ptr<GzipFile> file_;
  ReadProgress progress_;
  std::string buffer_;
  size_t buffer_pos_ = 0;
  bool eof_ = false;
  size_t line_no_ = 0;
  CarmenLogParams log_params_;
  std::map<std::string, std::optional<double>> saturation_;
  std::map<std::string, double> largest_;
  std::map<std::string, TimestampSequence> stamps_;
  std::map<std::string, std::string> reported_geometry_;
  size_t printed_malformed_ = 0, printed_timestamps_ = 0, printed_geometry_ = 0;
  CarmenStats stats_;
  std::optional<CarmenRecord> pending_;  ///< a scan to return after its line's odometry
};

/** Human-readable summary of a conversion, one fact per line. */
std::string formatCarmenStats(const CarmenStats& stats);

}  // namespace swslam::io
