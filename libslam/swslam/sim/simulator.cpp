#include <swslam/sim/simulator.h>

#include <swslam/sim/scenario_check.h>

#include <swslam/common/gzip_output.h>
#include <swslam/common/tum_io.h>
#include <swslam/sim/changes.h>
#include <swslam/sim/grid.h>
#include <swslam/sim/sensor.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>
#include <swslam/sim/writer.h>

#include <mrpt/core/format.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
namespace fs = std::filesystem;

void summarizeValidity(std::vector<double> valid, double rate, SimulationSummary& s)
{
  if (valid.empty()) return;
  double run = 0, mean = 0;
  for (double v : valid)
  {
    run = v < 0.1 ? run + 1 : 0;
    s.longest_sparse_seconds = std::max(s.longest_sparse_seconds, run / rate);
    mean += v;
  }
  s.valid_mean = mean / valid.size();
  std::sort(valid.begin(), valid.end());
  s.valid_min = valid.front();
  s.valid_median = valid[valid.size() / 2];
}
}  // namespace

SimulationSummary runSimulation(const Scenario& sc, const std::string& output_dir)
{
  validateScenario(sc);
  const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  World world = generateWorld(sc, path);
  checkPathFits(sc, world, path);
  const std::vector<WorldChange> changes = applyChanges(world, sc.changes, path);
  const ShapeGrid grid(world, sc.world.grid_cell);

  // Everything is checked: outputs from here on.
  fs::create_directories(output_dir);
  const fs::path base = fs::path(output_dir) / sc.name;
  SimulationSummary sum;
  sum.name = sc.name;
  sum.path_length = path.length();
  sum.duration = path.duration();
  sum.shapes = world.shapes.size();

  LidarSimulator lidar(sc.sensor, grid, sc.world.noise_seed);
  OdometrySimulator odometry(sc.odometry.speed_noise_std, sc.odometry.yaw_drift,
                             sc.odometry.yaw_noise_std, mix64(sc.world.noise_seed ^ 0x0D0ull));
  sum.rays_per_scan = lidar.rays();
  const size_t scans = static_cast<size_t>(std::floor(path.duration() * sc.sensor.rate)) + 1;
  std::vector<common::StampedPose> truth;
  std::vector<double> valid;
  truth.reserve(scans);
  valid.reserve(scans);

  const auto t0 = std::chrono::steady_clock::now();
  const std::string rawlog = base.string() + ".rawlog";
  common::writeGzipAtomically(rawlog, 1, [&](mrpt::io::CStream& file) {
    auto out = mrpt::serialization::archiveFrom(file);
    for (size_t k = 0; k < scans; k++)
    {
      // Times from the scenario's start time only: the same seed gives the same bytes.
      const double t = static_cast<double>(k) / sc.sensor.rate;
      const auto stamp = mrpt::Clock::fromDouble(sc.vehicle.start_time + t);
      const mrpt::poses::CPose2D pose = path.poseAt(t);
      truth.push_back({mrpt::Clock::toDouble(stamp), pose});
      if (sc.odometry.enabled)
      {
        auto odo = mrpt::obs::CObservationOdometry::Create();
        odo->sensorLabel = "ODOMETRY";
        odo->timestamp = stamp;
        odo->odometry = odometry.next(pose, k == 0 ? 0.0 : 1.0 / sc.sensor.rate);
        out << *odo;
      }
      const auto scan = lidar.scan(pose, stamp, k);
      size_t n_valid = 0;
      for (size_t i = 0; i < scan->getScanSize(); i++) n_valid += scan->getScanRangeValidity(i);
      valid.push_back(static_cast<double>(n_valid) / lidar.rays());
      out << *scan;
    }
  });
  sum.generation_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sum.scans = scans;
  summarizeValidity(valid, sc.sensor.rate, sum);

  common::writeTum(base.string() + ".gt.tum", truth);
  writeMrptGroundTruth(base.string() + ".gt.txt", truth);
  writeWorldPicture(base.string() + "_world.png", world, path.samples());
  if (sc.changes.any()) writeChanges(base.string() + ".changes.csv", changes);
  for (const char* ext : {".rawlog", ".gt.tum", ".gt.txt", "_world.png", ".changes.csv"})
  {
    if (std::string(ext) == ".changes.csv" && !sc.changes.any()) continue;
    const std::string f = base.string() + ext;
    sum.files.emplace_back(f, fs::file_size(f));
  }
  return sum;
}

std::string formatSummary(const SimulationSummary& s)
{
  std::string out = mrpt::format(
      "%s: %zu scans x %zu rays, %.1f m in %.1f s, %zu shapes\n"
      "  generated in %.2f s: %.0f scans/s\n"
      "  valid rays per scan: min %.1f%%, median %.1f%%, mean %.1f%%; "
      "longest stretch below 10%%: %.1f s\n",
      s.name.c_str(), s.scans, s.rays_per_scan, s.path_length, s.duration, s.shapes,
      s.generation_seconds, s.scans / std::max(s.generation_seconds, 1e-9), 100 * s.valid_min,
      100 * s.valid_median, 100 * s.valid_mean, s.longest_sparse_seconds);
  for (const auto& [file, bytes] : s.files)
    out += mrpt::format("  %-40s %10.2f KiB\n", file.c_str(), bytes / 1024.0);
  return out;
}

}  // namespace swslam::sim
