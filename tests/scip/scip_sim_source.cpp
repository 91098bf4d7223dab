#include "scip_sim_source.h"

#include <swslam/sim/grid.h>
#include <swslam/sim/scenario_check.h>
#include <swslam/sim/sensor.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace swslam::scip
{
struct SimScanSource::Impl
{
  sim::Scenario sc;
  sim::VehiclePath path;
  sim::World world;
  sim::ShapeGrid grid;
  sim::LidarSimulator lidar;

  explicit Impl(const sim::Scenario& s)
      : sc(s),
        path(s.vehicle.waypoints, s.vehicle.closed, s.vehicle.speed),
        world(sim::generateWorld(s, path)),
        grid(world, s.world.grid_cell),
        lidar(s.sensor, grid, s.world.seed)
  {
    sim::checkPathFits(sc, world, path);
  }
};

SimScanSource::SimScanSource(const sim::Scenario& sc, const SensorInfo& sensor)
{
  sim::validateScenario(sc);
  const double step = 2 * M_PI / sensor.ares;
  const auto near = [](double a, double b) { return std::abs(a - b) < 1e-9 * std::max(1.0, b); };
  if (!near(sc.sensor.resolution, step) ||
      !near(sc.sensor.fov, (sensor.amax - sensor.amin) * step) ||
      !near(sc.sensor.rate, sensor.scanRate()))
  {
    std::ostringstream msg;
    msg << "scenario '" << sc.name << "': [sensor] fov_DEG = " << sc.sensor.fov * 180 / M_PI
        << ", resolution_DEG = " << sc.sensor.resolution * 180 / M_PI
        << ", rate_hz = " << sc.sensor.rate << " do not match the emulated " << sensor.model
        << " (" << (sensor.amax - sensor.amin) * 360.0 / sensor.ares << " deg, "
        << 360.0 / sensor.ares << " deg, " << sensor.scanRate() << " Hz)";
    throw std::invalid_argument(msg.str());
  }
  impl_ = std::make_shared<Impl>(sc);
}

mrpt::poses::CPose2D SimScanSource::pose(uint64_t k) const
{
  return impl_->path.poseAt(static_cast<double>(k) / impl_->sc.sensor.rate);
}

uint64_t SimScanSource::pathScans() const
{
  return static_cast<uint64_t>(std::floor(impl_->path.duration() * impl_->sc.sensor.rate)) + 1;
}

double SimScanSource::rate() const { return impl_->sc.sensor.rate; }

Scan SimScanSource::operator()(uint64_t k) const
{
  const double t = static_cast<double>(k) / impl_->sc.sensor.rate;
  const auto stamp = mrpt::Clock::fromDouble(impl_->sc.vehicle.start_time + t);
  const auto obs = impl_->lidar.scan(impl_->path.poseAt(t), stamp, k);
  Scan scan;
  scan.ranges_mm.resize(obs->getScanSize());
  for (size_t i = 0; i < scan.ranges_mm.size(); i++)
    scan.ranges_mm[i] = obs->getScanRangeValidity(i)
                            ? static_cast<uint32_t>(std::lround(obs->getScanRange(i) * 1000.0))
                            : kNoEcho;
  return scan;
}

}  // namespace swslam::scip
