#pragma once
// A simulator scenario: the world, the vehicle's run and the sensors, one .ini section
// per parameter struct, each declared in its table (common/param_table.h). Every key is
// required and unknown keys are errors, so a misspelled key never silently falls back to a
// default.

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace swslam::sim
{
/** [world] Extent of the world (centered on the origin) and the random seed. */
struct WorldParams
{
  unsigned seed = 1;
  /** Seed of the sensor and odometry noise (ini key optional: defaults to `seed`), so that
   * runs can repeat the same world and path with other noise. */
  unsigned noise_seed = 1;
  double size_x = 200, size_y = 200;  ///< [m]
  double grid_cell = 2.0;             ///< spatial index cell size [m]

  static const common::ParamTable<WorldParams>& table();
};

/** [terrain] A lake (water inside an irregular shore), an optional island, rocks.
 * lake_radius = 0 means no water at all (a forest for a ground vehicle). */
struct TerrainParams
{
  double lake_center_x = 0, lake_center_y = 0, lake_radius = 90;
  double lake_roughness = 4;  ///< amplitude of the shore's irregularity [m]
  /** Probability that a LiDAR ray reaching the shore from the water passes over the
   * low bank and goes on over the land (0: an opaque bank). */
  double bank_pass_through = 0;
  double island_center_x = 0, island_center_y = 0;
  double island_radius = 0;   ///< 0: no island
  double island_roughness = 4;
  unsigned rocks = 5;         ///< rocks scattered in the water
  double rock_radius_min = 0.3, rock_radius_max = 1.2;

  static const common::ParamTable<TerrainParams>& table();
};

/** [vegetation] Trunks and bushes on the land near the shore (everywhere without
 * water), reeds in the water along the shore. Densities per 100 m^2 or per 100 m. */
struct VegetationParams
{
  double land_band = 20;          ///< vegetated land beyond the shore [m]
  double trunk_density = 2;       ///< mean trunks per 100 m^2 of vegetated land
  double density_variation = 0.5; ///< 0: uniform; 1: from clearings to twice the mean
  double trunk_radius_min = 0.1, trunk_radius_max = 0.4;
  double bush_density = 1;        ///< bushes per 100 m^2 of vegetated land
  double bush_radius = 1.0;       ///< radius of a bush [m]
  unsigned bush_leaves = 10;      ///< leaf clusters (small circles) per bush
  double bush_pass_through = 0.5; ///< probability a ray goes through one leaf cluster
  double reed_density = 5;        ///< reed clusters per 100 m of shore
  unsigned reed_stems = 15;       ///< stems per cluster
  double reed_pass_through = 0.4;
  double path_clearance = 2.0;    ///< no vegetation or rock closer to the path [m]

  static const common::ParamTable<VegetationParams>& table();
};

/** [vehicle] A smooth path through waypoints at constant speed. */
struct VehicleParams
{
  std::vector<Eigen::Vector2d> waypoints{{0, 0}, {10, 0}};
  bool closed = false;            ///< the path returns to its first waypoint
  double speed = 1.5;             ///< [m/s]
  double max_turn_rate = 0.5;     ///< [rad/s] (key max_turn_rate_DEG, in deg/s)
  double start_time = 1.7e9;      ///< timestamp of the first scan [s, UNIX time]

  static const common::ParamTable<VehicleParams>& table();
};

/** [sensor] A 2D LiDAR (defaults: Hokuyo UTM-30LX-like, as in the paper). */
struct SensorParams
{
  std::string label = "LIDAR";
  double fov = mrpt::DEG2RAD(270.0);    ///< [rad] (key fov_DEG)
  double resolution = mrpt::DEG2RAD(0.25);  ///< [rad] (key resolution_DEG)
  double max_range = 60, min_range = 0.1;  ///< [m]
  double rate = 40;                     ///< scans per second [Hz]
  double range_noise_std = 0.03;        ///< Gaussian range noise [m]
  double dropout_prob = 0.0;            ///< probability a ray returns nothing
  double pose_x = 0, pose_y = 0, pose_z = 0.3, pose_yaw = 0;  ///< mounting on the vehicle

  /** Number of rays: fov / resolution + 1. */
  size_t rays() const;

  static const common::ParamTable<SensorParams>& table();
};

/** [odometry] Optional noisy odometry observations, one per scan. */
struct OdometryParams
{
  bool enabled = true;
  double speed_noise_std = 0.02;  ///< relative std of each travelled increment
  double yaw_drift = 0;           ///< constant yaw-rate bias [rad/s] (key yaw_drift_DEG_per_s)
  double yaw_noise_std = 0;       ///< std of each yaw increment [rad] (key yaw_noise_std_DEG)

  static const common::ParamTable<OdometryParams>& table();
};

/** [changes] (optional section) The same world with rocks taken away and put: a later survey
 * of a place that changed (doc/sessions.md, "What changed"). */
struct ChangesParams
{
  unsigned seed = 1;
  unsigned remove = 0;        ///< rocks of radius >= 0.5 m taken away, among those in the band below
  unsigned add = 0;           ///< rocks put on the water, in the band
  double radius = 0.75;       ///< [m] of the rocks put
  double min_distance = 4;    ///< [m] the band: at least this far from the path...
  double max_distance = 25;   ///< [m] ...and at most this far

  bool any() const { return remove > 0 || add > 0; }
  static const common::ParamTable<ChangesParams>& table();
};

/** [building] (optional section) Walls: straight segments that stop every ray, for indoor
 * runs (a building's corridors and rooms). */
struct BuildingParams
{
  using Wall = std::pair<Eigen::Vector2d, Eigen::Vector2d>;
  std::vector<Wall> walls;

  bool any() const { return !walls.empty(); }
  static const common::ParamTable<BuildingParams>& table();
};

struct Scenario
{
  std::string name;  ///< output file stem
  WorldParams world;
  TerrainParams terrain;
  VehicleParams vehicle;
  SensorParams sensor;
  VegetationParams vegetation;
  OdometryParams odometry;
  ChangesParams changes;  ///< none unless the file has a [changes] section
  BuildingParams building;  ///< no walls unless the file has a [building] section
};

/** Reads and checks a scenario file; the name is the file's stem. Throws
 * std::invalid_argument naming the file, section and key on a missing, unknown or
 * malformed key or a value out of range. */
Scenario loadScenario(const std::string& path);

/** The scenario as .ini text that loadScenario() reads back (the name is not stored). */
std::string formatScenario(const Scenario& s);


/** Parses "x1 y1 x2 y2, ..." (at least one wall, none of zero length). Throws
 * std::invalid_argument. */
std::vector<BuildingParams::Wall> parseWalls(const std::string& text);
std::string formatWalls(const std::vector<BuildingParams::Wall>& walls);

/** Parses "x y, x y, ..." (at least two points). Throws std::invalid_argument. */
std::vector<Eigen::Vector2d> parseWaypoints(const std::string& text);
std::string formatWaypoints(const std::vector<Eigen::Vector2d>& pts);

}  // namespace swslam::sim
