#include <swslam/io/carmen_scan.h>

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <sstream>

namespace swslam::io
{
namespace
{
std::optional<double> lookup(const CarmenLogParams& p, const std::string& name)
{
  const auto it = p.find(name);
  if (it == p.end()) return std::nullopt;
  return it->second;
}

double deg(double rad) { return rad * 180.0 / M_PI; }

/** FLASER/RLASER: aperture from PARAM laser_<sensor>_laser_fov, else 180 degrees;
 * a resolution PARAM that does not fit the beam count is reported. */
double flaserAperture(const CarmenLaser& laser, const std::string& sensor,
                      const CarmenLogParams& p, std::string& warning)
{
  const double aperture =
      lookup(p, "laser_" + sensor + "_laser_fov").value_or(180.0) * M_PI / 180.0;
  if (const auto res_deg = lookup(p, "laser_" + sensor + "_laser_resolution"))
  {
    const double res = *res_deg * M_PI / 180.0, n = laser.ranges.size();
    const double tol = 1e-3;
    if (std::abs((n - 1) * res - aperture) > tol && std::abs(n * res - aperture) > tol)
    {
      std::ostringstream ss;
      ss << laser.label << ": PARAM resolution " << *res_deg << " deg x " << n
         << " beams does not span the FOV of " << deg(aperture) << " deg; using the FOV";
      warning = ss.str();
    }
  }
  return aperture;
}

}  // namespace

mrpt::poses::CPose2D carmenOffsetPose(const std::string& sensor, const CarmenLogParams& p)
{
  const std::string key = sensor == "front" ? "robot_frontlaser_" : "robot_rearlaser_";
  if (sensor != "front" && sensor != "rear") return {};
  const mrpt::poses::CPose2D offset(lookup(p, key + "offset").value_or(0),
                                    lookup(p, key + "side_offset").value_or(0),
                                    lookup(p, key + "angular_offset").value_or(0));
  if (sensor == "front") return offset;
  return mrpt::poses::CPose2D(0, 0, M_PI) + offset;
}

bool carmenParamIsUsed(const std::string& name)
{
  for (const std::string sensor : {"front", "rear"})
  {
    for (const char* suffix : {"offset", "side_offset", "angular_offset"})
      if (name == "robot_" + sensor + "laser_" + suffix) return true;
    if (name == "robot_" + sensor + "_laser_max" || name == "laser_" + sensor + "_laser_fov" ||
        name == "laser_" + sensor + "_laser_resolution")
      return true;
  }
  return false;
}

CarmenScanGeometry carmenScanGeometry(const CarmenLaser& laser, const CarmenLogParams& log_params,
                                      const CarmenParams& params,
                                      std::optional<double> saturation, double largest)
{
  CarmenScanGeometry g;
  const std::string sensor = carmenSensorOf(laser.label);
  const size_t n = laser.ranges.size();
  if (laser.has_geometry)
  {
    // Beam i is at start_angle + i * resolution: the MRPT scan is centred on the middle
    // beam, and the sensor pose turns by that centre angle.
    g.aperture = laser.resolution > 0 && n > 1 ? (n - 1) * laser.resolution : laser.fov;
    const double centre = laser.start_angle + g.aperture / 2;
    const mrpt::poses::CPose2D mount =
        laser.has_laser_pose ? carmenLaserMounting(laser) : carmenOffsetPose(sensor, log_params);
    g.sensor_pose = mount + mrpt::poses::CPose2D(0, 0, centre);
  }
  else
  {
    g.aperture = flaserAperture(laser, sensor, log_params, g.warning);
    g.sensor_pose = carmenOffsetPose(sensor, log_params);
  }

  const auto param_max = lookup(log_params, "robot_" + sensor + "_laser_max");
  if (params.max_range > 0)
    g.max_range = params.max_range, g.max_range_source = "option max_range";
  else if (laser.has_geometry && laser.max_range > 0)
    g.max_range = laser.max_range, g.max_range_source = "line field maximum_range";
  else if (param_max && *param_max > 0)
    g.max_range = *param_max, g.max_range_source = "PARAM robot_" + sensor + "_laser_max";
  else if (saturation)
    g.max_range = *saturation, g.max_range_source = "saturation detected";
  else
    g.max_range = largest + 0.01, g.max_range_source = "no saturation: largest reading + 1 cm";
  return g;
}

mrpt::obs::CObservation2DRangeScan::Ptr carmenScan(const CarmenLaser& laser,
                                                   const CarmenScanGeometry& g, double timestamp)
{
  auto obs = mrpt::obs::CObservation2DRangeScan::Create();
  obs->sensorLabel = laser.label;
  obs->timestamp = mrpt::Clock::fromDouble(timestamp);
  obs->aperture = static_cast<float>(g.aperture);
  obs->maxRange = static_cast<float>(g.max_range);
  obs->rightToLeft = true;  // CARMEN beams run counter-clockwise from start_angle
  obs->sensorPose = mrpt::poses::CPose3D(g.sensor_pose);
  obs->resizeScan(laser.ranges.size());
  for (size_t i = 0; i < laser.ranges.size(); i++)
  {
    const float r = laser.ranges[i];
    obs->setScanRange(i, r);
    obs->setScanRangeValidity(i, std::isfinite(r) && r > 0 && r < obs->maxRange);
  }
  return obs;
}

}  // namespace swslam::io
