#include <swslam/sim/scenario.h>
#include <swslam/sim/scenario_check.h>

#include <swslam/common/config_keys.h>
#include <swslam/common/param_table.h>
#include <swslam/common/ini_file.h>

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

/** Every key the struct writes must be in the file (no silent defaults), except the few
 * whose documented default is another key's value. */
void checkAllKeysPresent(const CConfigFileBase& cfg, const std::string& section,
                         const mrpt::config::CLoadableOptions& params)
{
  mrpt::config::CConfigFileMemory known;
  params.saveToConfigFile(known, section);
  std::vector<std::string> keys;
  known.getAllKeys(section, keys);
  for (const auto& key : keys)
    if (!cfg.keyExists(section, key) && !(section == "world" && key == "noise_seed"))
      throw std::invalid_argument("missing key " + where(section, key));
}

template <class Params>
Params loadSection(const CConfigFileBase& cfg, const std::string& section)
{
  if (!cfg.sectionExists(section)) throw std::invalid_argument("missing section [" + section + "]");
  common::checkKnownKeys(cfg, section, Params());  // first: a misspelled key is named as such
  checkAllKeysPresent(cfg, section, Params());
  return common::loadStrict<Params>(cfg, section);
}

/** Full precision, so that formatScenario() round-trips. */
void put(CConfigFileBase& c, const std::string& s, const std::string& key, double v)
{
  c.write(s, key, mrpt::format("%.15g", v));
}

/** The plain-number keys of a parameter struct: key name and member. */
template <class T>
using NumberKeys = std::vector<std::pair<const char*, double T::*>>;

template <class T>
void loadNumbers(T& p, const NumberKeys<T>& keys, const CConfigFileBase& c, const std::string& s)
{
  for (const auto& [key, member] : keys) p.*member = readDouble(c, s, key);
}

template <class T>
void saveNumbers(const T& p, const NumberKeys<T>& keys, CConfigFileBase& c, const std::string& s)
{
  for (const auto& [key, member] : keys) put(c, s, key, p.*member);
}

const NumberKeys<WorldParams> kWorldNumbers{
    {"size_x", &WorldParams::size_x},
    {"size_y", &WorldParams::size_y},
    {"grid_cell", &WorldParams::grid_cell}};

const NumberKeys<TerrainParams> kTerrainNumbers{
    {"lake_center_x", &TerrainParams::lake_center_x},
    {"lake_center_y", &TerrainParams::lake_center_y},
    {"lake_radius", &TerrainParams::lake_radius},
    {"lake_roughness", &TerrainParams::lake_roughness},
    {"bank_pass_through", &TerrainParams::bank_pass_through},
    {"island_center_x", &TerrainParams::island_center_x},
    {"island_center_y", &TerrainParams::island_center_y},
    {"island_radius", &TerrainParams::island_radius},
    {"island_roughness", &TerrainParams::island_roughness},
    {"rock_radius_min", &TerrainParams::rock_radius_min},
    {"rock_radius_max", &TerrainParams::rock_radius_max}};

const NumberKeys<VegetationParams> kVegetationNumbers{
    {"land_band", &VegetationParams::land_band},
    {"trunk_density", &VegetationParams::trunk_density},
    {"density_variation", &VegetationParams::density_variation},
    {"trunk_radius_min", &VegetationParams::trunk_radius_min},
    {"trunk_radius_max", &VegetationParams::trunk_radius_max},
    {"bush_density", &VegetationParams::bush_density},
    {"bush_radius", &VegetationParams::bush_radius},
    {"bush_pass_through", &VegetationParams::bush_pass_through},
    {"reed_density", &VegetationParams::reed_density},
    {"reed_pass_through", &VegetationParams::reed_pass_through},
    {"path_clearance", &VegetationParams::path_clearance}};

const NumberKeys<SensorParams> kSensorNumbers{
    {"max_range", &SensorParams::max_range},
    {"min_range", &SensorParams::min_range},
    {"rate_hz", &SensorParams::rate},
    {"range_noise_std", &SensorParams::range_noise_std},
    {"dropout_prob", &SensorParams::dropout_prob},
    {"pose_x", &SensorParams::pose_x},
    {"pose_y", &SensorParams::pose_y},
    {"pose_z", &SensorParams::pose_z}};
}  // namespace

void WorldParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
  seed = readUnsigned(c, s, "seed");
  noise_seed = c.keyExists(s, "noise_seed") ? readUnsigned(c, s, "noise_seed") : seed;
  loadNumbers(*this, kWorldNumbers, c, s);
}
void WorldParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  c.write(s, "seed", seed);
  c.write(s, "noise_seed", noise_seed);
  saveNumbers(*this, kWorldNumbers, c, s);
}

void TerrainParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
  loadNumbers(*this, kTerrainNumbers, c, s);
  rocks = readUnsigned(c, s, "rocks");
}
void TerrainParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  saveNumbers(*this, kTerrainNumbers, c, s);
  c.write(s, "rocks", rocks);
}

void VegetationParams::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
  loadNumbers(*this, kVegetationNumbers, c, s);
  bush_leaves = readUnsigned(c, s, "bush_leaves");
  reed_stems = readUnsigned(c, s, "reed_stems");
}
void VegetationParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  saveNumbers(*this, kVegetationNumbers, c, s);
  c.write(s, "bush_leaves", bush_leaves);
  c.write(s, "reed_stems", reed_stems);
}

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
  pose_yaw = readDegrees(c, s, "pose_yaw_DEG");
  loadNumbers(*this, kSensorNumbers, c, s);
}
void SensorParams::saveToConfigFile(CConfigFileBase& c, const std::string& s) const
{
  c.write(s, "label", label);
  put(c, s, "fov_DEG", mrpt::RAD2DEG(fov));
  put(c, s, "resolution_DEG", mrpt::RAD2DEG(resolution));
  put(c, s, "pose_yaw_DEG", mrpt::RAD2DEG(pose_yaw));
  saveNumbers(*this, kSensorNumbers, c, s);
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
    const auto file = common::readIniFile(path);
    const mrpt::config::CConfigFileBase& cfg = *file;
    common::checkKnownSections(cfg, {"world", "terrain", "vegetation", "vehicle", "sensor", "odometry"});
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
