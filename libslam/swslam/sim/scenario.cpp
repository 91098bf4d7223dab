#include <swslam/sim/scenario.h>
#include <swslam/sim/scenario_check.h>

#include <swslam/common/ini_file.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/format.h>
#include <mrpt/system/string_utils.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace swslam::sim
{
using common::anyNumber;
using common::atLeast;

namespace
{
/** A seed or a count: a whole number in [0, 1e9]. */
const common::Range kCount = common::between(0, 1e9);

/** A text key's parser from `parse`, which throws std::invalid_argument on bad text: its
 * message follows the key's name. */
template <class P, class T, class Parse>
auto parsedBy(T P::*member, Parse parse)
{
  return [member, parse](P& p, const std::string& v) {
    try
    {
      p.*member = parse(v);
      return std::string();
    }
    catch (const std::invalid_argument& e)
    {
      return std::string(": ") + e.what();
    }
  };
}
}  // namespace

const common::ParamTable<WorldParams>& WorldParams::table()
{
  using P = WorldParams;
  static const auto t = common::ParamTable<P>("world", "Extent of the world (centred on the origin) and the random seed.")
                            .integer("seed", &P::seed, "", kCount, "seed of the world")
                            .integer("noise_seed", &P::noise_seed, "", kCount, "seed of the sensor and odometry noise (default: seed)")
                            .real("size_x", &P::size_x, "m", anyNumber(), "extent along x")
                            .real("size_y", &P::size_y, "m", anyNumber(), "extent along y")
                            .real("grid_cell", &P::grid_cell, "m", anyNumber(), "spatial index cell size");
  return t;
}

const common::ParamTable<TerrainParams>& TerrainParams::table()
{
  using P = TerrainParams;
  static const auto t =
      common::ParamTable<P>("terrain", "A lake (water inside an irregular shore), an optional island, rocks.")
          .real("lake_center_x", &P::lake_center_x, "m", anyNumber(), "lake centre")
          .real("lake_center_y", &P::lake_center_y, "m", anyNumber(), "lake centre")
          .real("lake_radius", &P::lake_radius, "m", anyNumber(), "lake radius (0: no water)")
          .real("lake_roughness", &P::lake_roughness, "m", anyNumber(), "amplitude of the shore's irregularity")
          .real("bank_pass_through", &P::bank_pass_through, "", anyNumber(),
                "probability that a ray from the water passes over the low bank")
          .real("island_center_x", &P::island_center_x, "m", anyNumber(), "island centre")
          .real("island_center_y", &P::island_center_y, "m", anyNumber(), "island centre")
          .real("island_radius", &P::island_radius, "m", anyNumber(), "island radius (0: no island)")
          .real("island_roughness", &P::island_roughness, "m", anyNumber(), "amplitude of the island's irregularity")
          .real("rock_radius_min", &P::rock_radius_min, "m", anyNumber(), "rock radius, least...")
          .real("rock_radius_max", &P::rock_radius_max, "m", anyNumber(), "...and largest")
          .integer("rocks", &P::rocks, "", kCount, "rocks scattered in the water");
  return t;
}

const common::ParamTable<VegetationParams>& VegetationParams::table()
{
  using P = VegetationParams;
  static const auto t =
      common::ParamTable<P>("vegetation", "Trunks and bushes on land near the shore, reeds in the water along it.")
          .real("land_band", &P::land_band, "m", anyNumber(), "vegetated land beyond the shore")
          .real("trunk_density", &P::trunk_density, "", anyNumber(), "mean trunks per 100 m^2 of vegetated land")
          .real("density_variation", &P::density_variation, "", anyNumber(), "0: uniform; 1: from clearings to twice the mean")
          .real("trunk_radius_min", &P::trunk_radius_min, "m", anyNumber(), "trunk radius, least...")
          .real("trunk_radius_max", &P::trunk_radius_max, "m", anyNumber(), "...and largest")
          .real("bush_density", &P::bush_density, "", anyNumber(), "bushes per 100 m^2 of vegetated land")
          .real("bush_radius", &P::bush_radius, "m", anyNumber(), "radius of a bush")
          .real("bush_pass_through", &P::bush_pass_through, "", anyNumber(), "probability a ray goes through one leaf cluster")
          .real("reed_density", &P::reed_density, "", anyNumber(), "reed clusters per 100 m of shore")
          .real("reed_pass_through", &P::reed_pass_through, "", anyNumber(), "probability a ray goes through a reed cluster")
          .real("path_clearance", &P::path_clearance, "m", anyNumber(), "no vegetation or rock closer to the path")
          .integer("bush_leaves", &P::bush_leaves, "", kCount, "leaf clusters per bush")
          .integer("reed_stems", &P::reed_stems, "", kCount, "stems per reed cluster");
  return t;
}

const common::ParamTable<VehicleParams>& VehicleParams::table()
{
  using P = VehicleParams;
  static const auto t =
      common::ParamTable<P>("vehicle", "A smooth path through waypoints at constant speed.")
          .custom(
              "waypoints",
              parsedBy(&P::waypoints, parseWaypoints),
              [](const P& p) { return formatWaypoints(p.waypoints); }, "'x y, x y, ...' [m]")
          .flag("closed", &P::closed, "the path returns to its first waypoint")
          .real("speed", &P::speed, "m/s", anyNumber(), "vehicle speed")
          .angle("max_turn_rate_DEG", &P::max_turn_rate, anyNumber(), "largest turn rate [deg/s]")
          .real("start_time", &P::start_time, "s", anyNumber(), "timestamp of the first scan (UNIX time)");
  return t;
}

size_t SensorParams::rays() const
{
  return static_cast<size_t>(std::llround(fov / resolution)) + 1;
}

const common::ParamTable<SensorParams>& SensorParams::table()
{
  using P = SensorParams;
  static const auto t =
      common::ParamTable<P>("sensor", "A 2D LiDAR.")
          .text("label", &P::label, "sensor label of the observations")
          .angle("fov_DEG", &P::fov, anyNumber(), "field of view")
          .angle("resolution_DEG", &P::resolution, anyNumber(), "angle between rays")
          .angle("pose_yaw_DEG", &P::pose_yaw, anyNumber(), "mounting yaw on the vehicle")
          .real("max_range", &P::max_range, "m", anyNumber(), "longest range")
          .real("min_range", &P::min_range, "m", anyNumber(), "shortest range")
          .real("rate_hz", &P::rate, "Hz", anyNumber(), "scans per second")
          .real("range_noise_std", &P::range_noise_std, "m", anyNumber(), "Gaussian range noise")
          .real("dropout_prob", &P::dropout_prob, "", anyNumber(), "probability a ray returns nothing")
          .real("pose_x", &P::pose_x, "m", anyNumber(), "mounting on the vehicle")
          .real("pose_y", &P::pose_y, "m", anyNumber(), "mounting on the vehicle")
          .real("pose_z", &P::pose_z, "m", anyNumber(), "mounting on the vehicle");
  return t;
}

const common::ParamTable<OdometryParams>& OdometryParams::table()
{
  using P = OdometryParams;
  static const auto t =
      common::ParamTable<P>("odometry", "Optional noisy odometry observations, one per scan.")
          .flag("enabled", &P::enabled, "write odometry observations")
          .real("speed_noise_std", &P::speed_noise_std, "", anyNumber(), "relative std of each travelled increment")
          .angle("yaw_drift_DEG_per_s", &P::yaw_drift, anyNumber(), "constant yaw-rate bias [deg/s]")
          .angle("yaw_noise_std_DEG", &P::yaw_noise_std, anyNumber(), "std of each yaw increment");
  return t;
}

const common::ParamTable<ChangesParams>& ChangesParams::table()
{
  using P = ChangesParams;
  static const auto t =
      common::ParamTable<P>("changes", "The same world with rocks taken away and put (a later survey of a changed place).")
          .integer("seed", &P::seed, "", kCount, "which rocks, and where")
          .integer("remove", &P::remove, "", common::between(0, 1000), "rocks of radius >= 0.5 m taken away")
          .integer("add", &P::add, "", common::between(0, 1000), "rocks put on the water")
          .real("radius", &P::radius, "m", common::between(0.1, 10), "radius of the rocks put")
          .real("min_distance", &P::min_distance, "m", common::between(0, 1000), "the band: at least this far from the path...")
          .real("max_distance", &P::max_distance, "m", common::between(0, 1000), "...and at most this far")
          .rule([](const P& p) { return p.min_distance < p.max_distance; }, "min_distance must be below max_distance");
  return t;
}

const common::ParamTable<BuildingParams>& BuildingParams::table()
{
  using P = BuildingParams;
  static const auto t =
      common::ParamTable<P>("building", "Walls that stop every ray (indoor runs).")
          .custom(
              "walls",
              parsedBy(&P::walls, parseWalls),
              [](const P& p) { return formatWalls(p.walls); }, "'x1 y1 x2 y2, ...' [m], one segment per wall");
  return t;
}

namespace
{
/** Calls visit(table, parameters) for each section, in file order. */
template <class S, class Visit>
void forEachSection(S& sc, Visit visit)
{
  visit(WorldParams::table(), sc.world);
  visit(TerrainParams::table(), sc.terrain);
  visit(VegetationParams::table(), sc.vegetation);
  visit(VehicleParams::table(), sc.vehicle);
  visit(SensorParams::table(), sc.sensor);
  visit(OdometryParams::table(), sc.odometry);
}
}  // namespace

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

std::vector<BuildingParams::Wall> parseWalls(const std::string& text)
{
  std::vector<std::string> items;
  mrpt::system::tokenize(text, ",;", items);
  std::vector<BuildingParams::Wall> walls;
  for (const auto& item : items)
  {
    std::istringstream ss(item);
    double x1, y1, x2, y2;
    std::string rest;
    if (!(ss >> x1 >> y1 >> x2 >> y2) || (ss >> rest) || !std::isfinite(x1) || !std::isfinite(y1) ||
        !std::isfinite(x2) || !std::isfinite(y2))
      throw std::invalid_argument("wall '" + mrpt::system::trim(item) + "' is not 'x1 y1 x2 y2' (walls are 'x1 y1 x2 y2, ...')");
    if (x1 == x2 && y1 == y2) throw std::invalid_argument("wall '" + mrpt::system::trim(item) + "' has no length");
    walls.emplace_back(Eigen::Vector2d(x1, y1), Eigen::Vector2d(x2, y2));
  }
  if (walls.empty()) throw std::invalid_argument("need at least one wall 'x1 y1 x2 y2, ...'");
  return walls;
}

std::string formatWalls(const std::vector<BuildingParams::Wall>& walls)
{
  std::string s;
  for (const auto& [a, b] : walls)
    s += (s.empty() ? "" : ", ") + mrpt::format("%.15g %.15g %.15g %.15g", a.x(), a.y(), b.x(), b.y());
  return s;
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
  forEachSection(sc, [&](const auto& table, const auto& p) { table.save(p, c); });
  if (sc.changes.any()) ChangesParams::table().save(sc.changes, c);
  if (sc.building.any()) BuildingParams::table().save(sc.building, c);
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
    common::checkKnownSections(cfg, {"world", "terrain", "vegetation", "vehicle", "sensor", "odometry", "changes", "building"});
    Scenario sc;
    sc.name = std::filesystem::path(path).stem().string();
    // A misspelled key is named as such first, then a missing one.
    forEachSection(sc, [&](const auto& table, auto& p) {
      table.load(cfg, p);
      table.requireAll(cfg, {"noise_seed"});
    });
    if (!cfg.keyExists("world", "noise_seed")) sc.world.noise_seed = sc.world.seed;
    if (cfg.sectionExists("changes"))
    {
      ChangesParams::table().load(cfg, sc.changes);
      ChangesParams::table().requireAll(cfg);
    }
    if (cfg.sectionExists("building"))
    {
      BuildingParams::table().load(cfg, sc.building);
      BuildingParams::table().requireAll(cfg);
    }
    validateScenario(sc);
    return sc;
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument("scenario '" + path + "': " + e.what());
  }
}

}  // namespace swslam::sim
