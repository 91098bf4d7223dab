#include <swslam/system/input_gate.h>

#include <swslam/common/unix_time.h>
#include <swslam/sensor/scan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace swslam::system
{
namespace
{
bool isFinite(const mrpt::poses::CPose2D& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.phi());
}
}  // namespace

FeedResult InputGate::admit(sensor::ScanInput& input)
{
  if (!input.observation) return {FeedStatus::BadGeometry, "no observation"};
  const double t = mrpt::Clock::toDouble(input.observation->timestamp);
  if (!common::plausibleUnixTime(t))
  {
    char buf[120];
    std::snprintf(buf, sizeof(buf), "timestamp %.6g s is outside 1970-2200", t);
    return {FeedStatus::TimestampOutOfRange, buf + common::timeUnitHint(t)};
  }
  FeedResult result;
  // A jitter is one scan out of step after one that went forward: a clock that does not run
  // (every stamp equal, or microseconds that MRPT's clock turned to 0) is no jitter.
  const bool jitter = options_.timestamp_step_back > 0 && last_went_forward_ && std::isfinite(t) &&
                      t <= last_timestamp_ && last_timestamp_ - t <= options_.timestamp_step_back;
  if (jitter)
  {
    char buf[200];
    std::snprintf(buf, sizeof(buf), "timestamp %.6f s is %s the latest taken (%.6f s): taken under its own stamp", t,
                  t == last_timestamp_ ? "equal to" : "a little before", last_timestamp_);
    result = {FeedStatus::TimestampStepBack, buf};
  }
  else if (!std::isfinite(t) || t <= last_timestamp_)
  {
    // Scans behind the last one taken, but in order among themselves: once there are
    // timestamp_resume_scans of them, that one had jumped forward and the log goes on here.
    const bool behind = std::isfinite(t) && t < last_timestamp_;
    behind_in_order_ = behind ? (behind_in_order_ > 0 && t > last_behind_ ? behind_in_order_ + 1 : 1) : 0;
    last_behind_ = t;
    const size_t resume = static_cast<size_t>(options_.timestamp_resume_scans);
    char buf[200];
    if (resume == 0 || behind_in_order_ < resume)
    {
      std::snprintf(buf, sizeof(buf), "timestamp %.6f s is %.3g s before the latest taken (%.6f s)", t,
                    last_timestamp_ - t, last_timestamp_);
      return {FeedStatus::TimestampNotIncreasing, buf};
    }
    std::snprintf(buf, sizeof(buf),
                  "%zu scans in order behind %.6f s: that stamp jumped forward; the log resumes at %.6f s",
                  behind_in_order_, last_timestamp_, t);
    result = {FeedStatus::TimestampsResumed, buf};
  }
  behind_in_order_ = 0;
  try
  {
    sensor::checkObservationGeometry(*input.observation);
  }
  catch (const std::invalid_argument& e)
  {
    return {FeedStatus::BadGeometry, e.what()};
  }
  // An odometry increment is checked where it enters: a value no vehicle reaches would become
  // the tracker's guess, the search's window and a map pose.
  const bool first = last_timestamp_ < 0;
  const double since_last = t - last_timestamp_;
  if (!jitter) last_timestamp_ = t;  // after a resumption, the log's clock goes on from here
  last_went_forward_ = !jitter && !first && since_last > 0;
  if (input.odometry_increment && !isFinite(*input.odometry_increment))
  {
    result = {FeedStatus::OdometryDropped,
              "odometry increment " + input.odometry_increment->asString() + " is not finite: ignored"};
    input.odometry_increment.reset();
  }
  else if (input.odometry_increment && options_.max_odometry_speed > 0 &&
           input.odometry_increment->norm() > options_.max_odometry_speed * std::max(since_last, 1.0))
  {
    char buf[240];
    std::snprintf(buf, sizeof(buf),
                  "odometry increment of %.6g m in %.3g s is beyond [system] max_odometry_speed (%g m/s): ignored",
                  input.odometry_increment->norm(), since_last, options_.max_odometry_speed);
    result = {FeedStatus::OdometryDropped, buf};
    input.odometry_increment.reset();
  }
  return result;
}

}  // namespace swslam::system
