#include "test_support.h"

#include <cmath>
#include <csignal>
#include <stdexcept>
#include <sys/resource.h>
#include <filesystem>
#include <limits>
#include <unistd.h>

namespace swslam::test
{
double World::cast(double x, double y, double a) const
{
  const double dx = std::cos(a), dy = std::sin(a);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segments)
  {
    // Solve (x,y) + t (dx,dy) = p0 + u (p1 - p0), t > 0, u in [0,1].
    const double ex = s.x1 - s.x0, ey = s.y1 - s.y0;
    const double den = dx * ey - dy * ex;
    if (std::abs(den) < 1e-12) continue;
    const double wx = s.x0 - x, wy = s.y0 - y;
    const double t = (wx * ey - wy * ex) / den;
    const double u = (wx * dy - wy * dx) / den;
    if (t > 1e-9 && u >= 0 && u <= 1) best = std::min(best, t);
  }
  for (const auto& c : circles)
  {
    const double fx = x - c.cx, fy = y - c.cy;
    const double b = fx * dx + fy * dy;
    const double disc = b * b - (fx * fx + fy * fy - c.r * c.r);
    if (disc < 0) continue;
    const double t = -b - std::sqrt(disc);
    if (t > 1e-9) best = std::min(best, t);
  }
  return best;
}

World roomWorld()
{
  World w;
  const double X = 10, Y = 6;
  w.segments = {{-X, -Y, X, -Y}, {X, -Y, X, 1}, {X, 1, 7, 1}, {7, 1, 7, Y},
                {7, Y, -X, Y},   {-X, Y, -X, -Y}, {-4, -2, -2, -3}};
  w.circles = {{3, 2, 0.4}, {-5, 3, 0.3}, {1, -4, 0.5}, {-7, -3, 0.25}};
  return w;
}

World corridorWorld()
{
  World w;
  w.segments = {{-200, -1, 200, -1}, {-200, 1, 200, 1}};
  return w;
}

World clutteredWorld(unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  World w;
  // Irregular bank along y ~ 8 m, and another at y ~ -14 m.
  for (double side : {8.0, -14.0})
  {
    double px = -40, py = side;
    for (double x = -39; x <= 40; x += 1.0)
    {
      const double y = side + 1.5 * std::sin(0.21 * x) + 0.6 * (U(rng) - 0.5);
      w.segments.push_back({px, py, x, y});
      px = x;
      py = y;
    }
  }
  // Tree trunks scattered on both banks.
  for (int k = 0; k < 120; k++)
  {
    const double x = -38 + 76 * U(rng);
    const bool north = U(rng) < 0.5;
    const double y = north ? 9.5 + 10 * U(rng) : -15.5 - 10 * U(rng);
    w.circles.push_back({x, y, 0.1 + 0.4 * U(rng)});
  }
  // A few rocks in the water.
  w.circles.push_back({5, 3, 0.6});
  w.circles.push_back({-6, -5, 0.8});
  return w;
}

mrpt::obs::CObservation2DRangeScan simulateObservation(const World& world,
                                                       const mrpt::poses::CPose2D& pose,
                                                       size_t beams, double aperture,
                                                       double max_range, double sigma,
                                                       std::mt19937& rng)
{
  std::normal_distribution<double> noise(0, sigma);
  mrpt::obs::CObservation2DRangeScan obs;
  obs.sensorLabel = "LASER";
  obs.aperture = static_cast<float>(aperture);
  obs.maxRange = static_cast<float>(max_range);
  obs.rightToLeft = true;
  obs.resizeScan(beams);
  for (size_t i = 0; i < beams; i++)
  {
    const double a = pose.phi() + sensor::beamAngle(i, beams, aperture);
    double r = world.cast(pose.x(), pose.y(), a);
    const bool hit = r < max_range;
    if (hit && sigma > 0) r += noise(rng);
    obs.setScanRange(i, static_cast<float>(hit ? r : max_range));
    obs.setScanRangeValidity(i, hit);
  }
  return obs;
}

std::string errorOf(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}

void withFileSizeLimit(size_t bytes, const std::function<void()>& f)
{
  rlimit old{};
  if (getrlimit(RLIMIT_FSIZE, &old) != 0) throw std::runtime_error("getrlimit failed");
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = old;
  limited.rlim_cur = bytes;
  if (setrlimit(RLIMIT_FSIZE, &limited) != 0) throw std::runtime_error("setrlimit failed");
  struct Restore
  {
    rlimit old;
    void (*previous)(int);
    ~Restore()
    {
      setrlimit(RLIMIT_FSIZE, &old);
      std::signal(SIGXFSZ, previous);
    }
  } restore{old, previous};
  f();
}

std::string tempDir(const std::string& name)
{
  namespace fs = std::filesystem;
  const fs::path p = fs::temp_directory_path() / ("swslam_test_" + name + "_" +
                                                  std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

}  // namespace swslam::test
