#pragma once
// A small simulator scenario for fast tests: a 60 m x 50 m lake corner with a cluttered,
// low bank, a 12 m path, a 181-ray sensor at 10 Hz.

#include <swslam/sim/scenario.h>

#include <fstream>
#include <string>

namespace swslam::test
{
inline sim::Scenario smallScenario(unsigned seed = 3)
{
  sim::Scenario sc;
  sc.name = "small";
  sc.world.seed = seed;
  sc.world.size_x = 60;
  sc.world.size_y = 50;
  sc.world.grid_cell = 2.0;
  sc.terrain.lake_center_x = 0;
  sc.terrain.lake_center_y = -10;
  sc.terrain.lake_radius = 22;
  sc.terrain.lake_roughness = 3;
  sc.terrain.bank_pass_through = 0.5;
  sc.terrain.island_radius = 0;
  sc.terrain.island_roughness = 0;
  sc.terrain.rocks = 3;
  sc.vegetation.land_band = 10;
  sc.vegetation.trunk_density = 6;
  sc.vegetation.bush_density = 2;
  sc.vegetation.reed_density = 10;
  sc.vegetation.path_clearance = 1.5;
  sc.vehicle.waypoints = {{-6, -8}, {0, -6}, {6, -8}};
  sc.vehicle.closed = false;
  sc.vehicle.speed = 1.5;
  sc.vehicle.max_turn_rate = 0.6;
  sc.vehicle.start_time = 1700000000.0;
  sc.sensor.fov = 270 * M_PI / 180;
  sc.sensor.resolution = 1.5 * M_PI / 180;
  sc.sensor.max_range = 25;
  sc.sensor.rate = 10;
  sc.sensor.dropout_prob = 0.02;
  return sc;
}

inline void writeText(const std::string& path, const std::string& text)
{
  std::ofstream(path) << text;
}

}  // namespace swslam::test
