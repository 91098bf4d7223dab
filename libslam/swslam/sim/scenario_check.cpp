// Value checks of a scenario: ranges and the sensor's geometry, each error naming its key.
#include <swslam/sim/scenario_check.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>

#include <cmath>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
void require(bool ok, const std::string& section, const std::string& key, const std::string& what)
{
  if (!ok) throw std::invalid_argument("[" + section + "] " + key + " " + what);
}
}  // namespace

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
  require(t.bank_pass_through >= 0 && t.bank_pass_through <= 1, "terrain", "bank_pass_through",
          "must be a probability in [0, 1]");
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
  require(g.density_variation >= 0 && g.density_variation <= 1, "vegetation",
          "density_variation", "must be in [0, 1]");
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

  const double hx = 0.5 * w.size_x, hy = 0.5 * w.size_y;
  for (const auto& [a, b] : sc.building.walls)
    for (const Eigen::Vector2d& p : {a, b})
      require(std::abs(p.x()) <= hx && std::abs(p.y()) <= hy, "building", "walls",
              mrpt::format("end (%g, %g) lies outside the world (size_x, size_y)", p.x(), p.y()));

  const auto& o = sc.odometry;
  require(o.speed_noise_std >= 0 && o.speed_noise_std < 1, "odometry", "speed_noise_std",
          "must be in [0, 1)");
  require(o.yaw_noise_std >= 0, "odometry", "yaw_noise_std_DEG", "must be >= 0");
}

}  // namespace swslam::sim
