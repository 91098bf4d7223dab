#include <swslam/io/carmen_line.h>

#include <swslam/common/tum_io.h>
#include <swslam/sensor/input_bounds.h>

#include <mrpt/poses/CPose3D.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace swslam::io
{
mrpt::poses::CPose2D carmenLaserMounting(const CarmenLaser& laser)
{
  return mrpt::poses::CPose2D(laser.laser_pose) - mrpt::poses::CPose2D(laser.robot_pose);
}

namespace
{
/** Largest beam or remission count accepted: far above any real 2D scanner, low enough
 * that a corrupt count cannot ask for gigabytes. */
constexpr long kMaxCount = 100000;

/** Reads the whitespace-separated fields of one message, naming the field on errors. */
class Fields
{
 public:
  explicit Fields(const std::string& line)
  {
    std::istringstream ss(line);
    std::string tok;
    while (ss >> tok) tokens_.push_back(tok);
  }
  bool empty() const { return tokens_.empty(); }
  const std::string& message() const { return tokens_.at(0); }
  size_t remaining() const { return tokens_.size() - next_; }

  const std::string& text(const char* what)
  {
    if (next_ >= tokens_.size())
      throw CarmenLineError(message() + ": line ends before field '" + what + "' (" +
                            std::to_string(tokens_.size()) + " fields)");
    return tokens_[next_++];
  }
  /** A number; non-finite values are rejected unless `allow_non_finite`. */
  double number(const char* what, bool allow_non_finite = false)
  {
    const std::string& t = text(what);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0')
      throw CarmenLineError(message() + ": field '" + what + "' is not a number: '" + t + "'");
    if (!allow_non_finite && !std::isfinite(v))
      throw CarmenLineError(message() + ": field '" + what + "' is not finite: '" + t + "'");
    return v;
  }
  size_t count(const char* what)
  {
    const std::string& t = text(what);
    char* end = nullptr;
    const long v = std::strtol(t.c_str(), &end, 10);
    if (end == t.c_str() || *end != '\0' || v < 0 || v > kMaxCount)
      throw CarmenLineError(message() + ": field '" + what + "' is not a count in [0, " +
                            std::to_string(kMaxCount) + "]: '" + t + "'");
    return static_cast<size_t>(v);
  }
  /** A pose: its position coordinates no larger than a trajectory file may hold
   * (common::kMaxTumCoordinate: the ground truth written from these poses reads back). */
  mrpt::math::TPose2D pose(const char* what)
  {
    const double x = number(what), y = number(what), phi = number(what);
    if (std::abs(x) > common::kMaxTumCoordinate || std::abs(y) > common::kMaxTumCoordinate)
    {
      std::ostringstream s;
      s << message() << ": field '" << what << "' has a position beyond " << common::kMaxTumCoordinate
        << " m: (" << x << ", " << y << ")";
      throw CarmenLineError(s.str());
    }
    return {x, y, phi};
  }
  /** The ipc timestamp, then optionally hostname and logger timestamp; nothing more. */
  double timestampAndEnd()
  {
    const double t = number("ipc_timestamp");
    if (remaining() > 2)
      throw CarmenLineError(message() + ": " + std::to_string(remaining() - 2) +
                            " unexpected field(s) after 'ipc_timestamp host logger_timestamp'");
    return t;
  }

 private:
  std::vector<std::string> tokens_;
  size_t next_ = 1;  // token 0 is the message name
};

void readRanges(Fields& f, CarmenLaser& laser)
{
  const size_t n = f.count("num_readings");
  if (f.remaining() < n)
    throw CarmenLineError(f.message() + ": num_readings is " + std::to_string(n) +
                          " but only " + std::to_string(f.remaining()) + " fields follow");
  laser.ranges.resize(n);
  for (size_t i = 0; i < n; i++)
    laser.ranges[i] = static_cast<float>(f.number("range", /*allow_non_finite=*/true));
}

/** Fields shared by ROBOTLASER* and RAWLASER*: geometry, ranges, remissions. */
void readLaserWithGeometry(Fields& f, CarmenLaser& laser)
{
  f.number("laser_type");
  laser.has_geometry = true;
  laser.start_angle = f.number("start_angle");
  laser.fov = f.number("field_of_view");
  laser.resolution = f.number("angular_resolution");
  laser.max_range = f.number("maximum_range");
  f.number("accuracy");
  f.number("remission_mode");
  readRanges(f, laser);
  const size_t m = f.count("num_remissions");
  for (size_t i = 0; i < m; i++) f.number("remission", /*allow_non_finite=*/true);
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

bool isRawLaser(const std::string& m)
{
  return m.size() == 9 && startsWith(m, "RAWLASER") && m[8] >= '1' && m[8] <= '4';
}
bool isRobotLaser(const std::string& m) { return m == "ROBOTLASER1" || m == "ROBOTLASER2"; }

}  // namespace

CarmenLine parseCarmenLine(const std::string& line)
{
  CarmenLine out;
  Fields f(line);
  if (f.empty()) return out;  // Kind::Blank
  const std::string msg = f.message();
  out.message = msg;
  if (msg[0] == '#') return out;  // Kind::Blank

  if (msg == "PARAM")
  {
    out.kind = CarmenLine::Kind::Param;
    out.param_name = f.text("param_name");
    out.param_value = f.text("param_value");
    return out;
  }
  if (msg == "ODOM")
  {
    out.kind = CarmenLine::Kind::Odometry;
    out.odometry.pose = f.pose("x y theta");
    out.odometry.tv = f.number("tv");
    out.odometry.rv = f.number("rv");
    f.number("accel");
    out.odometry.timestamp = f.timestampAndEnd();
    return out;
  }
  CarmenLaser& laser = out.laser;
  laser.label = msg;
  if (msg == "FLASER" || msg == "RLASER")
  {
    readRanges(f, laser);
    laser.has_pose = true;
    laser.robot_pose = f.pose("x y theta");
    laser.has_odometry = true;
    laser.odometry_pose = f.pose("odom_x odom_y odom_theta");
  }
  else if (isRobotLaser(msg))
  {
    readLaserWithGeometry(f, laser);
    laser.has_laser_pose = laser.has_pose = true;
    laser.laser_pose = f.pose("laser_pose_x y theta");
    laser.robot_pose = f.pose("robot_pose_x y theta");
    // Each pose may be within the trajectory's bounds and the two still far apart.
    if (const std::string problem = sensor::mountingProblem(mrpt::poses::CPose3D(carmenLaserMounting(laser)));
        !problem.empty())
      throw CarmenLineError(msg + ": laser_pose and robot_pose put the " + problem);
    for (const char* what : {"laser_tv", "laser_rv", "forward_safety_dist", "side_safety_dist",
                             "turn_axis"})
      f.number(what);
  }
  else if (isRawLaser(msg))
  {
    readLaserWithGeometry(f, laser);
  }
  else
  {
    out.kind = CarmenLine::Kind::Unknown;
    return out;
  }
  laser.timestamp = f.timestampAndEnd();
  out.kind = CarmenLine::Kind::Laser;
  return out;
}

std::string carmenSensorOf(const std::string& label)
{
  if (label == "FLASER" || label == "ROBOTLASER1" || label == "RAWLASER1") return "front";
  if (label == "RLASER" || label == "ROBOTLASER2" || label == "RAWLASER2") return "rear";
  if (label == "RAWLASER3") return "laser3";
  if (label == "RAWLASER4") return "laser4";
  return {};
}

}  // namespace swslam::io
