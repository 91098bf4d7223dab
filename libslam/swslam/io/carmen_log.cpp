#include <swslam/io/carmen_log.h>

#include <swslam/common/unix_time.h>
#include <swslam/io/text_encoding.h>
#include <swslam/sensor/input_bounds.h>

#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace swslam::io
{
namespace
{
/** A PARAM value as a finite number, if it is one. */
std::optional<double> numericParam(const std::string& value)
{
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (end == value.c_str() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}
}  // namespace

CarmenLogReader::CarmenLogReader(const std::string& path, const CarmenParams& params,
                                 WarningSink warn)
    : path_(path), params_(params), warn_(std::move(warn)), progress_(path)
{
  stats_.repairing = params_.repair_timestamps;
  params_.check();
  if (!warn_) warn_ = [](const std::string& m) { std::cerr << "warning: " << m << "\n"; };
  prescan();
  open();
}

void CarmenLogReader::open()
{
  try
  {
    if (!std::filesystem::is_regular_file(path_)) throw std::runtime_error("not a file");
    file_ = std::make_unique<GzipFile>(path_);
  }
  catch (const std::exception&)
  {
    throw std::runtime_error("carmen: cannot open '" + path_ + "'");
  }
  buffer_.clear();
  buffer_pos_ = 0;
  eof_ = false;
  line_no_ = 0;
}

bool CarmenLogReader::nextLine(std::string& line)
{
  line.clear();
  for (;;)
  {
    const size_t nl = buffer_.find('\n', buffer_pos_);
    if (nl != std::string::npos)
    {
      line.append(buffer_, buffer_pos_, nl - buffer_pos_);
      buffer_pos_ = nl + 1;
      line_no_++;
      return true;
    }
    line.append(buffer_, buffer_pos_, std::string::npos);
    buffer_.resize(1 << 16);
    size_t got = 0;
    try
    {
      got = eof_ ? 0 : file_->read(buffer_.data(), buffer_.size());
    }
    catch (const GzipError& e)
    {
      buffer_.clear();
      throw GzipError("carmen: '" + path_ + "': " + e.what() + ", after line " + std::to_string(line_no_),
                      e.contentRead());
    }
    buffer_.resize(got);
    buffer_pos_ = 0;
    if (got == 0)
    {
      eof_ = true;
      if (line.empty()) return false;
      line_no_++;  // last line without '\n'
      return true;
    }
  }
}

struct CarmenLogReader::Prescan
{
  CarmenLogParams mountings;
  std::map<std::string, SaturationDetector> detectors;
  std::map<std::string, std::vector<double>> times;  ///< per laser label, and "ODOM"
  size_t stamps = 0, out_of_range = 0, first_out_line = 0, odom_lines = 0;
  bool laser_odometry = false;
  double first_out = 0;
};

void CarmenLogReader::prescan()
{
  // First pass: each laser's readings (saturation) and each stream's timestamps (repair
  // period), and the lasers' mountings that the PARAM lines state. Malformed lines are
  // skipped silently here; the second pass reports them.
  checkHead();
  Prescan p;
  std::string text;
  for (;;)
  {
    try
    {
      if (!nextLine(text)) break;
    }
    catch (const GzipError&)
    {
      break;  // the second pass reports it, after the lines before it
    }
    CarmenLine line;
    try
    {
      line = parseCarmenLine(text);
    }
    catch (const CarmenLineError&)
    {
      continue;
    }
    prescanLine(line, p);
  }
  stats_.odometry_source = p.odom_lines > 0    ? CarmenOdometrySource::OdomLines
                           : p.laser_odometry ? CarmenOdometrySource::LaserFields
                                              : CarmenOdometrySource::None;
  reportSaturation(p);
  checkStampsInRange(p);
  setTimestampRepair(p);
}

void CarmenLogReader::checkHead()
{
  open();
  std::string head(4096, '\0');
  try
  {
    head.resize(file_->read(head.data(), head.size()));
  }
  catch (const GzipError&)
  {
    head.clear();  // the second pass reports it, after the lines before it
  }
  if (const std::string problem = wideTextProblem(head); !problem.empty())
    throw std::runtime_error("carmen: '" + path_ + "' " + problem);
  open();
}

void CarmenLogReader::prescanLine(const CarmenLine& line, Prescan& p)
{
  if (line.kind == CarmenLine::Kind::Param && carmenParamIsUsed(line.param_name))
    if (const auto v = numericParam(line.param_value))
    {
      p.mountings[line.param_name] = *v;
      for (const std::string sensor : {"front", "rear"})
        if (const std::string problem = sensor::mountingProblem(mrpt::poses::CPose3D(carmenOffsetPose(sensor, p.mountings)));
            !problem.empty())
          throw std::runtime_error("carmen: '" + path_ + "' line " + std::to_string(line_no_) + ": PARAM " +
                                   line.param_name + " " + line.param_value + " puts the " + sensor + " laser's " +
                                   problem + ": not converted");
    }
  if (line.kind == CarmenLine::Kind::Odometry) p.odom_lines++;
  if (line.kind == CarmenLine::Kind::Laser) p.laser_odometry |= line.laser.has_odometry;
  const bool odometry = line.kind == CarmenLine::Kind::Odometry && !params_.laser_only;
  if (!odometry && line.kind != CarmenLine::Kind::Laser) return;
  const double stamp = odometry ? line.odometry.timestamp : line.laser.timestamp;
  p.stamps++;
  if (!stampInRange(stamp))
  {
    if (p.out_of_range++ == 0)
    {
      p.first_out = stamp;
      p.first_out_line = line_no_;
    }
    return;
  }
  if (odometry)
  {
    p.times["ODOM"].push_back(stamp);
    return;
  }
  const auto& laser = line.laser;
  p.times[laser.label].push_back(laser.timestamp);
  auto it = p.detectors.try_emplace(laser.label, params_.saturation_rel_tol, params_.saturation_min_count).first;
  for (float r : laser.ranges) it->second.add(r);
}

void CarmenLogReader::reportSaturation(const Prescan& p)
{
  for (const auto& [label, d] : p.detectors)
  {
    saturation_[label] = d.threshold();
    largest_[label] = d.largest();
    if (const size_t glitches = d.glitchesAbove())
    {
      stats_.saturation_glitches += glitches;
      char buf[200];
      std::snprintf(buf, sizeof(buf), "%zu reading(s) above the saturation value %.2f m (largest %.2f m): glitches, "
                    "read as no return", glitches, *saturation_[label], d.largest());
      warn(printed_geometry_, path_ + ": " + label + ": " + buf);
    }
  }
}

void CarmenLogReader::checkStampsInRange(const Prescan& p) const
{
  if (p.out_of_range == 0 || 2 * p.out_of_range <= p.stamps) return;
  char buf[200];
  std::snprintf(buf, sizeof(buf), "%zu of %zu timestamps are out of range (beyond +-%.0f s, the year 2200; the first, %.6g, at line %zu)",
                p.out_of_range, p.stamps, common::kLatestPlausibleTime, p.first_out, p.first_out_line);
  throw std::runtime_error("carmen: '" + path_ + "': " + buf + common::timeUnitHint(p.first_out) + ": not converted");
}

void CarmenLogReader::setTimestampRepair(const Prescan& p)
{
  double earliest = 0;
  for (const auto& [stream, t] : p.times)
    if (stream != "ODOM" && !t.empty())
      earliest = std::min(earliest, *std::min_element(t.begin(), t.end()));
  stats_.timestamp_offset = -earliest;
  for (const auto& [stream, t] : p.times)
  {
    const double period = medianPositivePeriod(t, params_.max_timestamp_gap, params_.default_period);
    stamps_.emplace(stream, TimestampSequence(period, params_.max_timestamp_gap, params_.repair_timestamps));
    stats_.timestamps[stream].repair_period = period;
  }
}

void CarmenLogReader::warn(size_t& printed, const std::string& msg)
{
  if (printed++ < params_.max_printed_warnings) warn_(msg);
}

void CarmenLogReader::addParam(const std::string& name, const std::string& value)
{
  const auto v = numericParam(value);
  // Non-numeric values (on/off, device names) are fine for parameters the converter ignores.
  if (!v && carmenParamIsUsed(name))
    throw CarmenLineError("PARAM " + name + ": value '" + value + "' is not a finite number");
  stats_.params++;
  if (v) log_params_[name] = *v;
}

bool CarmenLogReader::stampInRange(double raw)
{
  // Negative stamps are shifted into the range (timestamp_offset): only their size is checked.
  return common::plausibleUnixTime(std::abs(raw));
}

bool CarmenLogReader::keepStamp(const std::string& stream, double raw)
{
  if (stampInRange(raw)) return true;
  stats_.timestamps[stream].out_of_range++;
  char buf[120];
  std::snprintf(buf, sizeof(buf), " timestamp %.6g s is out of range (beyond +-%.0f s, the year 2200)", raw,
                common::kLatestPlausibleTime);
  warn(printed_timestamps_, path_ + ":" + std::to_string(line_no_) + ": " + stream + buf +
                                common::timeUnitHint(raw) + ": line skipped");
  return false;
}

double CarmenLogReader::stampOf(const std::string& stream, double raw, size_t line)
{
  auto& counts = stats_.timestamps[stream];
  counts.count++;
  double shifted = raw + stats_.timestamp_offset;
  if (shifted < 0)
  {
    counts.negative++;
    warn(printed_timestamps_, path_ + ":" + std::to_string(line) + ": " + stream +
                                  " timestamp " + std::to_string(raw) +
                                  " is negative: not representable in MRPT, written as 0");
    shifted = 0;
  }
  TimestampIssue issue;
  const double t = stamps_.at(stream).next(shifted, issue);
  if (issue == TimestampIssue::None) return t;
  (issue == TimestampIssue::NonIncreasing ? counts.non_increasing : counts.forward_jumps)++;
  if (params_.repair_timestamps) counts.repaired++;
  warn(printed_timestamps_,
       path_ + ":" + std::to_string(line) + ": " + stream + " timestamp " + std::to_string(raw) +
           (issue == TimestampIssue::NonIncreasing ? " does not increase"
                                                   : " jumps forward by more than " +
                                                         std::to_string(params_.max_timestamp_gap) +
                                                         " s") +
           (params_.repair_timestamps ? ", replaced by " + std::to_string(t) : ""));
  return t;
}

void CarmenLogReader::convertLaser(const CarmenLaser& laser, CarmenRecord& record)
{
  const auto geometry = carmenScanGeometry(laser, log_params_, params_, saturation_[laser.label],
                                           largest_[laser.label]);
  if (!geometry.warning.empty() && reported_geometry_[laser.label] != geometry.warning)
  {
    stats_.geometry_warnings++;
    reported_geometry_[laser.label] = geometry.warning;
    warn(printed_geometry_, path_ + ":" + std::to_string(line_no_) + ": " + geometry.warning);
  }
  record.raw_timestamp = laser.timestamp;
  record.timestamp = stampOf(laser.label, laser.timestamp, line_no_);
  auto scan = carmenScan(laser, geometry, record.timestamp);
  if (laser.has_pose) record.reference_pose = mrpt::poses::CPose2D(laser.robot_pose);

  auto& s = stats_.lasers[laser.label];
  const size_t n = laser.ranges.size();
  s.min_beams = s.scans == 0 ? n : std::min(s.min_beams, n);
  s.max_beams = std::max(s.max_beams, n);
  s.scans++;
  s.rays += n;
  for (size_t i = 0; i < n; i++) s.invalid_rays += scan->getScanRangeValidity(i) ? 0 : 1;
  s.aperture = geometry.aperture;
  s.max_range = geometry.max_range;
  s.max_range_source = geometry.max_range_source;
  record.observation = scan;
}

CarmenRecord CarmenLogReader::laserOdometry(const CarmenLaser& laser, const CarmenRecord& scan)
{
  // As an ODOM line would give it, at the scan's own (written) time: the run then reads the
  // odometry at the scan exactly. The line has no velocities.
  auto obs = mrpt::obs::CObservationOdometry::Create();
  obs->sensorLabel = "ODOM";
  obs->timestamp = scan.observation->timestamp;
  obs->odometry = mrpt::poses::CPose2D(laser.odometry_pose);
  CarmenRecord record;
  record.observation = obs;
  record.timestamp = scan.timestamp;
  record.raw_timestamp = scan.raw_timestamp;
  record.line = scan.line;
  stats_.odometry++;
  return record;
}

bool CarmenLogReader::next(CarmenRecord& record)
{
  record = CarmenRecord();
  if (pending_)
  {
    record = std::move(*pending_);
    pending_.reset();
    return true;
  }
  std::string text;
  while (nextLine(text))
  {
    stats_.lines++;
    CarmenLine line;
    try
    {
      line = parseCarmenLine(text);
      if (line.kind == CarmenLine::Kind::Param) addParam(line.param_name, line.param_value);
    }
    catch (const CarmenLineError& e)
    {
      if (stats_.malformed++ == 0) stats_.first_malformed_line = line_no_;
      warn(printed_malformed_,
           path_ + ":" + std::to_string(line_no_) + ": malformed line skipped: " + e.what());
      continue;
    }
    record.line = line_no_;
    switch (line.kind)
    {
      case CarmenLine::Kind::Blank: continue;
      case CarmenLine::Kind::Unknown: stats_.unknown_messages[line.message]++; continue;
      case CarmenLine::Kind::Param: continue;
      case CarmenLine::Kind::Laser:
        if (!keepStamp(line.laser.label, line.laser.timestamp)) continue;
        convertLaser(line.laser, record);
        if (stats_.odometry_source == CarmenOdometrySource::LaserFields && line.laser.has_odometry)
        {
          if (params_.laser_only)
            stats_.odometry_dropped++;
          else
          {
            pending_ = std::move(record);
            record = laserOdometry(line.laser, *pending_);
          }
        }
        return true;
      case CarmenLine::Kind::Odometry:
      {
        if (params_.laser_only)
        {
          stats_.odometry_dropped++;
          continue;
        }
        const auto& o = line.odometry;
        if (!keepStamp("ODOM", o.timestamp)) continue;
        auto obs = mrpt::obs::CObservationOdometry::Create();
        obs->sensorLabel = "ODOM";
        record.raw_timestamp = o.timestamp;
        record.timestamp = stampOf("ODOM", o.timestamp, line_no_);
        obs->timestamp = mrpt::Clock::fromDouble(record.timestamp);
        obs->odometry = mrpt::poses::CPose2D(o.pose);
        obs->hasVelocities = true;
        obs->velocityLocal = mrpt::math::TTwist2D(o.tv, 0, o.rv);
        record.observation = obs;
        stats_.odometry++;
        return true;
      }
    }
  }
  return false;
}

double CarmenLogReader::fractionRead() const { return progress_.fraction(file_->position()); }

size_t CarmenStats::timestampProblems() const
{
  size_t n = 0;
  for (const auto& [stream, t] : timestamps) n += t.non_increasing + t.forward_jumps + t.negative + t.out_of_range;
  return n;
}

size_t CarmenStats::scans() const
{
  size_t n = 0;
  for (const auto& [label, s] : lasers) n += s.scans;
  return n;
}

}  // namespace swslam::io
