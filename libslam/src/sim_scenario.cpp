#include "swslam/sim_scenario.h"

#include "swslam/config_keys.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/system/string_utils.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
using mrpt::config::CConfigFileBase;

std::string where(const std::string& s, const std::string& key)
{
  return "[" + s + "] " + key;
}

// Strict readers: the key has been checked present; a value that does not parse
// entirely is an error naming the key (MRPT's own readers would read "abc" as 0).
double readDouble(const CConfigFileBase& c, const std::string& s, const std::string& key)
{
  const std::string v = mrpt::system::trim(c.read_string(s, key, "", true));
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x))
    throw std::invalid_argument(where(s, key) + " = '" + v + "' is not a finite number");
  return x;
}

unsigned readUnsigned(const CConfigFileBase& c, const std::string& s, const std::string& key)
{
  const double x = readDouble(c, s, key);
  if (x < 0 || x != std::floor(x) || x > 1e9)
    throw std::invalid_argument(where(s, key) + " must be a non-negative integer");
  return static_cast<unsigned>(x);
}

bool readBool(const CConfigFileBase& c, const std::string& s, const std::string& key)
{
  const std::string v = mrpt::system::lowerCase(mrpt::system::trim(c.read_string(s, key, "", true)));
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  throw std::invalid_argument(where(s, key) + " = '" + v + "' is not true/false");
}

double readDegrees(const CConfigFileBase& c, const std::string& s, const std::string& key)
{
  return mrpt::DEG2RAD(readDouble(c, s, key));
}

/** Every key the struct writes must be in the file: no silent defaults. */
void checkAllKeysPresent(const CConfigFileBase& cfg, const std::string& section,
                         const mrpt::config::CLoadableOptions& params)
{
  mrpt::config::CConfigFileMemory known;
  params.saveToConfigFile(known, section);
  std::vector<std::string> keys;
  known.getAllKeys(section, keys);
  for (const auto& key : keys)
    if (!cfg.keyExists(section, key))
      throw std::invalid_argument("missing key " + where(section, key));
}

template <class Params>
Params loadSection(const CConfigFileBase& cfg, const std::string& section)
{
  if (!cfg.sectionExists(section)) throw std::invalid_argument("missing section [" + section + "]");
  checkKnownKeys(cfg, section, Params());  // first: a misspelled key is named as such
  checkAllKeysPresent(cfg, section, Params());
  return loadStrict<Params>(cfg, section);
}

/** Full precision, so that formatScenario() round-trips. */
void put(CConfigFileBase& c, const std::string& s, const std::string& key, double v)
{
  c.write(s, key, mrpt::format("%.15g", v));
}

void require(bool ok, const std::string& section, const std::string& key, const std::string& what)
{
  if (!ok) throw std::invalid_argument(where(section, key) + " " + what);
}
}  // namespace

void WorldParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
  seed = readUnsigned(c, s, "seed");
  size_x = readDouble(c, s, "size_x");
  size_y = readDouble(c, s, "size_y");
  grid_cell = readDouble(c, s, "grid_cell");
}
void WorldParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  c.write(s, "seed", seed);
  put(c, s, "size_x", size_x);
  put(c, s, "size_y", size_y);
  put(c, s, "grid_cell", grid_cell);
}

#define SWSLAM_DOUBLE_KEYS(X)                                                                    \
  X(lake_center_x) X(lake_center_y) X(lake_radius) X(lake_roughness) X(island_center_x)         \
  X(island_center_y) X(island_radius) X(island_roughness) X(rock_radius_min) X(rock_radius_max)
void TerrainParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
#define X(k) k = readDouble(c, s, #k);
  SWSLAM_DOUBLE_KEYS(X)
#undef X
  rocks = readUnsigned(c, s, "rocks");
}
void TerrainParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
#define X(k) put(c, s, #k, k);
  SWSLAM_DOUBLE_KEYS(X)
#undef X
  c.write(s, "rocks", rocks);
}
#undef SWSLAM_DOUBLE_KEYS

#define SWSLAM_DOUBLE_KEYS(X)                                                                    \
  X(land_band) X(trunk_density) X(trunk_radius_min) X(trunk_radius_max) X(bush_density)         \
  X(bush_radius) X(bush_pass_through) X(reed_density) X(reed_pass_through) X(path_clearance)
void VegetationParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
#define X(k) k = readDouble(c, s, #k);
  SWSLAM_DOUBLE_KEYS(X)
#undef X
  bush_leaves = readUnsigned(c, s, "bush_leaves");
  reed_stems = readUnsigned(c, s, "reed_stems");
}
void VegetationParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
#define X(k) put(c, s, #k, k);
  SWSLAM_DOUBLE_KEYS(X)
#undef X
  c.write(s, "bush_leaves", bush_leaves);
  c.write(s, "reed_stems", reed_stems);
}
#undef SWSLAM_DOUBLE_KEYS

void VehicleParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
  try
  {
    waypoints = parseWaypoints(c.read_string(s, "waypoints", "", true));
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument(where(s, "waypoints") + ": " + e.what());
  }
  closed = readBool(c, s, "closed");
  speed = readDouble(c, s, "speed");
  max_turn_rate = readDegrees(c, s, "max_turn_rate_DEG");
  start_time = readDouble(c, s, "start_time");
}
void VehicleParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  c.write(s, "waypoints", formatWaypoints(waypoints));
  c.write(s, "closed", closed);
  put(c, s, "speed", speed);
  put(c, s, "max_turn_rate_DEG", mrpt::RAD2DEG(max_turn_rate));
  put(c, s, "start_time", start_time);
}

size_t SensorParams::rays() const
{
  return static_cast<size_t>(std::llround(fov / resolution)) + 1;
}

void SensorParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
  label = mrpt::system::trim(c.read_string(s, "label", "", true));
  fov = readDegrees(c, s, "fov_DEG");
  resolution = readDegrees(c, s, "resolution_DEG");
  max_range = readDouble(c, s, "max_range");
  min_range = readDouble(c, s, "min_range");
  rate = readDouble(c, s, "rate_hz");
  range_noise_std = readDouble(c, s, "range_noise_std");
  dropout_prob = readDouble(c, s, "dropout_prob");
  pose_x = readDouble(c, s, "pose_x");
  pose_y = readDouble(c, s, "pose_y");
  pose_z = readDouble(c, s, "pose_z");
  pose_yaw = readDegrees(c, s, "pose_yaw_DEG");
}
void SensorParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  c.write(s, "label", label);
  put(c, s, "fov_DEG", mrpt::RAD2DEG(fov));
  put(c, s, "resolution_DEG", mrpt::RAD2DEG(resolution));
  put(c, s, "max_range", max_range);
  put(c, s, "min_range", min_range);
  put(c, s, "rate_hz", rate);
  put(c, s, "range_noise_std", range_noise_std);
  put(c, s, "dropout_prob", dropout_prob);
  put(c, s, "pose_x", pose_x);
  put(c, s, "pose_y", pose_y);
  put(c, s, "pose_z", pose_z);
  put(c, s, "pose_yaw_DEG", mrpt::RAD2DEG(pose_yaw));
}

void OdometryParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
  enabled = readBool(c, s, "enabled");
  speed_noise_std = readDouble(c, s, "speed_noise_std");
  yaw_drift = readDegrees(c, s, "yaw_drift_DEG_per_s");
  yaw_noise_std = readDegrees(c, s, "yaw_noise_std_DEG");
}
void OdometryParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  c.write(s, "enabled", enabled);
  put(c, s, "speed_noise_std", speed_noise_std);
  put(c, s, "yaw_drift_DEG_per_s", mrpt::RAD2DEG(yaw_drift));
  put(c, s, "yaw_noise_std_DEG", mrpt::RAD2DEG(yaw_noise_std));
}

std::vector<Eigen::Vector2d> parseWaypoints(const std::string& text)
{
  std::vector<std::string> items;
  mrpt::system::tokenize(text, ",;", items);
  std::vector<Eigen::Vector2d> pts;
  for (const auto& item : items)
  {
    std::istringstream ss(item);
    double x, y;
    std::string rest;
    if (!(ss >> x >> y) || (ss >> rest) || !std::isfinite(x) || !std::isfinite(y))
      throw std::invalid_argument("waypoint '" + mrpt::system::trim(item) +
                                  "' is not 'x y' (waypoints are 'x y, x y, ...')");
    pts.emplace_back(x, y);
  }
  if (pts.size() < 2) throw std::invalid_argument("need at least 2 waypoints 'x y, x y, ...'");
  return pts;
}

std::string formatWaypoints(const std::vector<Eigen::Vector2d>& pts)
{
  std::string s;
  for (const auto& p : pts) s += (s.empty() ? "" : ", ") + mrpt::format("%.15g %.15g", p.x(), p.y());
  return s;
}

void validateScenario(const Scenario& sc)
{
  const auto& w = sc.world;
  require(w.size_x > 0, "world", "size_x", "must be > 0");
  require(w.size_y > 0, "world", "size_y", "must be > 0");
  require(w.grid_cell >= 0.1 && w.grid_cell <= 50, "world", "grid_cell", "must be in [0.1, 50] m");

  const auto& t = sc.terrain;
  require(t.lake_radius >= 0, "terrain", "lake_radius", "must be >= 0 (0: no water)");
  require(t.lake_roughness >= 0 && t.lake_roughness <= 0.3 * t.lake_radius + 1e-9, "terrain",
          "lake_roughness", "must be in [0, 0.3 * lake_radius]");
  require(t.island_radius >= 0, "terrain", "island_radius", "must be >= 0 (0: no island)");
  require(t.island_roughness >= 0 && t.island_roughness <= 0.3 * t.island_radius + 1e-9,
          "terrain", "island_roughness", "must be in [0, 0.3 * island_radius]");
  require(t.rock_radius_min > 0, "terrain", "rock_radius_min", "must be > 0");
  require(t.rock_radius_max >= t.rock_radius_min, "terrain", "rock_radius_max",
          "must be >= rock_radius_min");

  const auto& g = sc.vegetation;
  require(g.land_band >= 0, "vegetation", "land_band", "must be >= 0");
  require(g.trunk_density >= 0 && g.trunk_density <= 100, "vegetation", "trunk_density",
          "must be in [0, 100] per 100 m^2");
  require(g.trunk_radius_min > 0, "vegetation", "trunk_radius_min", "must be > 0");
  require(g.trunk_radius_max >= g.trunk_radius_min, "vegetation", "trunk_radius_max",
          "must be >= trunk_radius_min");
  require(g.bush_density >= 0 && g.bush_density <= 100, "vegetation", "bush_density",
          "must be in [0, 100] per 100 m^2");
  require(g.bush_radius > 0, "vegetation", "bush_radius", "must be > 0");
  require(g.reed_density >= 0 && g.reed_density <= 1000, "vegetation", "reed_density",
          "must be in [0, 1000] per 100 m");
  require(g.bush_pass_through >= 0 && g.bush_pass_through < 1, "vegetation",
          "bush_pass_through", "must be a probability in [0, 1)");
  require(g.reed_pass_through >= 0 && g.reed_pass_through < 1, "vegetation",
          "reed_pass_through", "must be a probability in [0, 1)");
  require(g.path_clearance >= 0, "vegetation", "path_clearance", "must be >= 0");

  const auto& v = sc.vehicle;
  require(v.speed > 0 && v.speed <= 5, "vehicle", "speed", "must be in (0, 5] m/s");
  require(v.max_turn_rate > 0, "vehicle", "max_turn_rate_DEG", "must be > 0");
  require(v.start_time >= 0, "vehicle", "start_time", "must be >= 0");

  const auto& s = sc.sensor;
  require(!s.label.empty() && s.label.find_first_of(" \t") == std::string::npos, "sensor",
          "label", "must be one word");
  require(s.fov > 0 && s.fov <= 2 * M_PI + 1e-9, "sensor", "fov_DEG", "must be in (0, 360]");
  require(s.resolution > 0 && s.resolution <= s.fov, "sensor", "resolution_DEG",
          "must be in (0, fov_DEG]");
  const double steps = s.fov / s.resolution;
  require(std::abs(steps - std::round(steps)) < 1e-6, "sensor", "resolution_DEG",
          mrpt::format("= %g does not divide fov_DEG = %g", mrpt::RAD2DEG(s.resolution),
                       mrpt::RAD2DEG(s.fov)));
  require(s.min_range >= 0, "sensor", "min_range", "must be >= 0");
  require(s.max_range > s.min_range, "sensor", "max_range",
          mrpt::format("= %g must be > min_range = %g", s.max_range, s.min_range));
  require(s.rate > 0 && s.rate <= 1000, "sensor", "rate_hz", "must be in (0, 1000]");
  require(s.range_noise_std >= 0, "sensor", "range_noise_std", "must be >= 0");
  require(s.dropout_prob >= 0 && s.dropout_prob < 1, "sensor", "dropout_prob",
          "must be a probability in [0, 1)");

  const auto& o = sc.odometry;
  require(o.speed_noise_std >= 0 && o.speed_noise_std < 1, "odometry", "speed_noise_std",
          "must be in [0, 1)");
  require(o.yaw_noise_std >= 0, "odometry", "yaw_noise_std_DEG", "must be >= 0");
}

std::string formatScenario(const Scenario& sc)
{
  mrpt::config::CConfigFileMemory c;
  sc.world.saveToConfigFile(c, "world");
  sc.terrain.saveToConfigFile(c, "terrain");
  sc.vegetation.saveToConfigFile(c, "vegetation");
  sc.vehicle.saveToConfigFile(c, "vehicle");
  sc.sensor.saveToConfigFile(c, "sensor");
  sc.odometry.saveToConfigFile(c, "odometry");
  std::string text;
  c.getContent(text);
  return text;
}

Scenario loadScenario(const std::string& path)
{
  if (!std::filesystem::is_regular_file(path))
    throw std::invalid_argument("scenario '" + path + "' does not exist");
  try
  {
    const mrpt::config::CConfigFile cfg(path);
    checkKnownSections(cfg, {"world", "terrain", "vegetation", "vehicle", "sensor", "odometry"});
    Scenario sc;
    sc.name = std::filesystem::path(path).stem().string();
    sc.world = loadSection<WorldParams>(cfg, "world");
    sc.terrain = loadSection<TerrainParams>(cfg, "terrain");
    sc.vegetation = loadSection<VegetationParams>(cfg, "vegetation");
    sc.vehicle = loadSection<VehicleParams>(cfg, "vehicle");
    sc.sensor = loadSection<SensorParams>(cfg, "sensor");
    sc.odometry = loadSection<OdometryParams>(cfg, "odometry");
    validateScenario(sc);
    return sc;
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("scenario '" + path + "': " + e.what());
  }
}

}  // namespace swslam::sim
