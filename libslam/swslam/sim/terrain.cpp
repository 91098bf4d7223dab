#include <swslam/sim/terrain.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>
#include <mrpt/math/TSegment2D.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
using Vec = Eigen::Vector2d;
constexpr double kShoreVertexSpacing = 1.0;  // [m]
constexpr double kShoreJitter = 0.3;         // [m] small-scale irregularity of the shore
constexpr double kWaterMargin = 1.0;         // [m] the path stays this far from the shore
constexpr double kWallMargin = 0.5;          // [m] and this far from a wall

class Generator
{
 public:
  Generator(const Scenario& sc, const VehiclePath& path)
      : sc_(sc), rng_(mix64(sc.world.seed) ^ 0x5EEDull)
  {
    const double hx = 0.5 * sc.world.size_x, hy = 0.5 * sc.world.size_y;
    world_.bounds = {-hx, -hy, hx, hy};
    buildClearance(path);
  }

  World run()
  {
    const auto& t = sc_.terrain;
    if (t.lake_radius > 0)
    {
      world_.has_water = true;
      world_.lake = curve({t.lake_center_x, t.lake_center_y}, t.lake_radius, t.lake_roughness);
      if (t.island_radius > 0)
        world_.islands.push_back(
            curve({t.island_center_x, t.island_center_y}, t.island_radius, t.island_roughness));
      shore_length_ = addShore(world_.lake, true);
      for (const auto& island : world_.islands) shore_length_ += addShore(island, false);
    }
    for (const auto& [a, b] : sc_.building.walls) world_.add(Shape::segment(ShapeKind::Wall, a, b));
    addRocks();
    for (int i = 0; i < 4; i++)
    {
      const double k = 2 * M_PI / uniform(20, 60), a = uniform(-M_PI, M_PI);
      waves_.emplace_back(k * std::cos(a), k * std::sin(a), uniform(-M_PI, M_PI));
    }
    addTrunksAndBushes();
    addReeds();
    return std::move(world_);
  }

 private:
  const Scenario& sc_;
  std::mt19937_64 rng_;
  World world_;
  double shore_length_ = 0;
  std::vector<Eigen::Vector3d> waves_;  ///< (kx, ky, phase) of the density field
  // Raster of the cells near the path, where nothing may be placed.
  double clear_cell_ = 0.5;
  size_t clear_nx_ = 0, clear_ny_ = 0;
  std::vector<uint8_t> clear_;

  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  Vec uniformInWorld()
  {
    const Box& b = world_.bounds;
    return {uniform(b.min_x, b.max_x), uniform(b.min_y, b.max_y)};
  }
  Vec uniformInDisc(const Vec& c, double r)
  {
    const double a = uniform(-M_PI, M_PI), d = r * std::sqrt(uniform(0, 1));
    return c + d * Vec(std::cos(a), std::sin(a));
  }

  void buildClearance(const VehiclePath& path)
  {
    const Box& b = world_.bounds;
    clear_nx_ = static_cast<size_t>(std::ceil((b.max_x - b.min_x) / clear_cell_)) + 1;
    clear_ny_ = static_cast<size_t>(std::ceil((b.max_y - b.min_y) / clear_cell_)) + 1;
    clear_.assign(clear_nx_ * clear_ny_, 0);
    // Conservative: a cell is blocked if any of it may lie within the clearance.
    const double r = sc_.vegetation.path_clearance + clear_cell_;
    const long rc = static_cast<long>(std::ceil(r / clear_cell_));
    for (const Vec& p : path.samples())
    {
      const long cx = static_cast<long>((p.x() - b.min_x) / clear_cell_);
      const long cy = static_cast<long>((p.y() - b.min_y) / clear_cell_);
      for (long iy = cy - rc; iy <= cy + rc; iy++)
        for (long ix = cx - rc; ix <= cx + rc; ix++)
        {
          if (ix < 0 || iy < 0 || ix >= static_cast<long>(clear_nx_) ||
              iy >= static_cast<long>(clear_ny_))
            continue;
          const Vec center(b.min_x + (ix + 0.5) * clear_cell_, b.min_y + (iy + 0.5) * clear_cell_);
          if ((center - p).norm() <= r) clear_[iy * clear_nx_ + ix] = 1;
        }
    }
  }

  /** Whether a disc at `c` of radius `r` stays out of the path's clear lane. */
  bool awayFromPath(const Vec& c, double r) const
  {
    const Box& b = world_.bounds;
    const long x0 = static_cast<long>(std::floor((c.x() - r - b.min_x) / clear_cell_));
    const long x1 = static_cast<long>(std::floor((c.x() + r - b.min_x) / clear_cell_));
    const long y0 = static_cast<long>(std::floor((c.y() - r - b.min_y) / clear_cell_));
    const long y1 = static_cast<long>(std::floor((c.y() + r - b.min_y) / clear_cell_));
    for (long iy = std::max(0L, y0); iy <= std::min<long>(y1, clear_ny_ - 1); iy++)
      for (long ix = std::max(0L, x0); ix <= std::min<long>(x1, clear_nx_ - 1); ix++)
        if (clear_[iy * clear_nx_ + ix]) return false;
    return true;
  }

  void addCircle(ShapeKind kind, const Vec& c, double r, double pass = 0)
  {
    if (awayFromPath(c, r)) world_.add(Shape::circle(kind, c, r, pass));
  }

  PolarCurve curve(const Vec& center, double radius, double roughness)
  {
    // Harmonics 2..12 with amplitudes falling as 1/k, scaled so they sum to `roughness`.
    PolarCurve c;
    c.center = center;
    c.radius = radius;
    double sum = 0;
    for (int k = 2; k <= 12; k++)
    {
      c.amplitudes.push_back(uniform(0.3, 1.0) / k);
      c.phases.push_back(uniform(-M_PI, M_PI));
      sum += c.amplitudes.back();
    }
    for (double& a : c.amplitudes) a *= roughness / sum;
    return c;
  }

  /** Adds the shore as a closed chain of bank segments, water on their left (water
   * inside the curve: counter-clockwise); returns its length. */
  double addShore(const PolarCurve& c, bool water_inside)
  {
    const size_t n = std::max<size_t>(
        12, static_cast<size_t>(std::ceil(2 * M_PI * c.radius / kShoreVertexSpacing)));
    std::vector<Vec> v(n);
    for (size_t i = 0; i < n; i++)
    {
      const double a = 2 * M_PI * static_cast<double>(i) / n;
      const double r = c.radiusAt(a) + uniform(-kShoreJitter, kShoreJitter);
      v[i] = c.center + r * Vec(std::cos(a), std::sin(a));
    }
    double length = 0;
    for (size_t i = 0; i < n; i++)
    {
      const Vec &a = v[i], &b = v[(i + 1) % n];
      length += (b - a).norm();
      const double pass = sc_.terrain.bank_pass_through;
      world_.add(water_inside ? Shape::bank(a, b, pass) : Shape::bank(b, a, pass));
    }
    return length;
  }

  bool vegetatedLand(const Vec& p) const
  {
    if (!world_.has_water) return true;
    if (world_.isWater(p)) return false;
    const double band = sc_.vegetation.land_band;
    const double off = world_.lake.radialOffset(p);
    if (off >= kShoreJitter && off <= band) return true;
    for (const auto& island : world_.islands)
    {
      const double o = island.radialOffset(p);
      if (o <= -kShoreJitter && o >= -band) return true;
    }
    return false;
  }

  /** Relative vegetation density at `p`, in [0, 2] with mean about 1: a few random
   * plane waves of 20-60 m wavelength make thickets and clearings. */
  double densityField(const Vec& p) const
  {
    double sum = 0;
    for (const auto& w : waves_) sum += std::cos(w.x() * p.x() + w.y() * p.y() + w.z());
    return std::clamp(1.0 + sc_.vegetation.density_variation * 0.5 * sum, 0.0, 2.0);
  }

  /** Mean `density` per 100 m^2 of the part of the world where `accept` holds,
   * modulated by densityField (rejection sampling from twice the mean). */
  template <class Accept, class Place>
  void scatter(double density, Accept accept, Place place)
  {
    const Box& b = world_.bounds;
    const double area = (b.max_x - b.min_x) * (b.max_y - b.min_y);
    const long n = std::lround(2 * density * area / 100.0);
    for (long i = 0; i < n; i++)
    {
      const Vec p = uniformInWorld();
      const bool keep = uniform(0, 2) < densityField(p);
      if (keep && accept(p)) place(p);
    }
  }

  void addRocks()
  {
    const auto& t = sc_.terrain;
    if (!world_.has_water) return;
    for (unsigned i = 0, tries = 0; i < t.rocks && tries < 100000; tries++)
    {
      const Vec p = uniformInWorld();
      const double r = uniform(t.rock_radius_min, t.rock_radius_max);
      if (!world_.isWater(p) || !awayFromPath(p, r)) continue;
      world_.add(Shape::circle(ShapeKind::Rock, p, r));
      i++;
    }
  }

  void addTrunksAndBushes()
  {
    const auto& g = sc_.vegetation;
    const auto land = [&](const Vec& p) { return vegetatedLand(p); };
    scatter(g.trunk_density, land, [&](const Vec& p) {
      addCircle(ShapeKind::Trunk, p, uniform(g.trunk_radius_min, g.trunk_radius_max));
    });
    scatter(g.bush_density, land, [&](const Vec& p) {
      for (unsigned k = 0; k < g.bush_leaves; k++)
      {
        const double r = g.bush_radius * uniform(0.15, 0.35);
        addCircle(ShapeKind::Bush, uniformInDisc(p, g.bush_radius - r), r, g.bush_pass_through);
      }
    });
  }

  void addReeds()
  {
    const auto& g = sc_.vegetation;
    if (!world_.has_water || g.reed_stems == 0) return;
    const long clusters = std::lround(g.reed_density * shore_length_ / 100.0);
    std::vector<const PolarCurve*> shores{&world_.lake};
    for (const auto& island : world_.islands) shores.push_back(&island);
    for (long i = 0; i < clusters; i++)
    {
      // A shore point picked in proportion to the shore's size, then into the water.
      const PolarCurve* c = shores[0];
      if (shores.size() > 1 && uniform(0, 1) < shores[1]->radius / (c->radius + shores[1]->radius))
        c = shores[1];
      const double a = uniform(-M_PI, M_PI);
      const double into = uniform(1.0, 4.0) * (c == &world_.lake ? -1 : 1);
      const Vec center = c->center + (c->radiusAt(a) + into) * Vec(std::cos(a), std::sin(a));
      for (unsigned k = 0; k < g.reed_stems; k++)
      {
        const Vec p = uniformInDisc(center, 1.5);
        if (world_.isWater(p)) addCircle(ShapeKind::Reed, p, uniform(0.01, 0.03), g.reed_pass_through);
      }
    }
  }
};
}  // namespace

World generateWorld(const Scenario& sc, const VehiclePath& path)
{
  return Generator(sc, path).run();
}

void checkPathFits(const Scenario& sc, const World& world, const VehiclePath& path)
{
  const double turn = path.maxCurvature() * sc.vehicle.speed;
  if (turn > sc.vehicle.max_turn_rate)
  {
    const Vec p = path.maxCurvaturePoint();
    throw std::invalid_argument(mrpt::format(
        "[vehicle] waypoints: the path turns at %.1f deg/s near (%.1f, %.1f), more than "
        "max_turn_rate_DEG = %.1f at speed %.2f m/s: spread the waypoints or slow down",
        mrpt::RAD2DEG(turn), p.x(), p.y(), mrpt::RAD2DEG(sc.vehicle.max_turn_rate),
        sc.vehicle.speed));
  }
  // The sensor, mounted off the vehicle's origin, must stay inside the world too.
  const double m = std::hypot(sc.sensor.pose_x, sc.sensor.pose_y);
  const Box& b = world.bounds;
  const Box inner{b.min_x + m, b.min_y + m, b.max_x - m, b.max_y - m};
  for (const Vec& p : path.samples())
  {
    if (!inner.contains(p))
      throw std::invalid_argument(mrpt::format(
          "[vehicle] waypoints: the path leaves the world at (%.1f, %.1f); the world spans "
          "[%.1f, %.1f] x [%.1f, %.1f] ([world] size_x, size_y), less %.1f m for the sensor "
          "mounting",
          p.x(), p.y(), b.min_x, b.max_x, b.min_y, b.max_y, m));
    for (const auto& [wa, wb] : sc.building.walls)
      if (mrpt::math::TSegment2D({wa.x(), wa.y()}, {wb.x(), wb.y()}).distance({p.x(), p.y()}) < kWallMargin)
        throw std::invalid_argument(mrpt::format(
            "[vehicle] waypoints: the path comes within %.1f m of the wall (%g, %g)-(%g, %g) at (%.1f, %.1f)",
            kWallMargin, wa.x(), wa.y(), wb.x(), wb.y(), p.x(), p.y()));
    if (!world.has_water) continue;
    bool afloat = world.lake.radialOffset(p) < -kWaterMargin;
    for (const auto& island : world.islands) afloat = afloat && island.radialOffset(p) > kWaterMargin;
    if (!afloat)
      throw std::invalid_argument(mrpt::format(
          "[vehicle] waypoints: the path runs onto land (or within %.1f m of the shore) at "
          "(%.1f, %.1f)",
          kWaterMargin, p.x(), p.y()));
  }
}

}  // namespace swslam::sim
