#pragma once
// The simulated world: a rectangle of land and water holding the shapes a 2D LiDAR
// ray can hit (shoreline segments, rocks, tree trunks, bush leaves, reed stems).
// Bushes, reeds and the low bank let rays through with a per-shape probability;
// whether a given ray passes a given shape is a pure function of (ray key, shape
// index), so every ray-casting method gives the same answer for the same ray.

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <vector>

namespace swslam::sim
{
enum class ShapeKind : uint8_t
{
  Bank,   ///< shoreline segment
  Rock,
  Trunk,
  Bush,   ///< one leaf cluster of a bush
  Reed,   ///< one reed stem
  Wall,   ///< a building's wall segment (scenario [building])
};

/** A circle (`radius` > 0, center `a`) or a segment (`radius` == 0, from `a` to `b`). */
struct Shape
{
  ShapeKind kind = ShapeKind::Rock;
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  double radius = 0;
  double pass_through = 0;  ///< probability that a ray goes through it unseen
  /** A segment seen only by rays that cross it from its left side (left of a -> b);
   * rays from the right go through it. */
  bool one_sided = false;

  bool isCircle() const { return radius > 0; }
  static Shape circle(ShapeKind kind, const Eigen::Vector2d& c, double r, double pass = 0);
  static Shape segment(ShapeKind kind, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
  /** A shore segment with the water on its left: a bank rising from the water, seen
   * only from the water, that a ray passes over with probability `pass`. */
  static Shape bank(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double pass);
};

struct Box
{
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
  bool contains(const Eigen::Vector2d& p) const
  {
    return p.x() >= min_x && p.x() <= max_x && p.y() >= min_y && p.y() <= max_y;
  }
  bool contains(const Box& o) const
  {
    return o.min_x >= min_x && o.max_x <= max_x && o.min_y >= min_y && o.max_y <= max_y;
  }
};

/** Axis-aligned bounding box of a shape. */
Box boundingBox(const Shape& s);

/** A closed irregular curve r(theta) = radius + sum_k amp_k cos(k theta + phase_k)
 * around `center`: a lake shore (water inside) or an island shore (land inside). */
struct PolarCurve
{
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0;
  std::vector<double> amplitudes, phases;  ///< harmonic k = index + 2

  double radiusAt(double theta) const;
  /** Signed radial distance: > 0 outside the curve, < 0 inside. */
  double radialOffset(const Eigen::Vector2d& p) const;
};

/** A ray from `origin` along the unit vector `dir`. `key` identifies the ray
 * (scan and beam) and drives the pass-through draws. */
struct Ray
{
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();
  uint64_t key = 0;
};

constexpr double kNoHit = std::numeric_limits<double>::infinity();

/** Distance along `ray` to where it enters `s`, or kNoHit. A ray starting inside a
 * circle does not see it, nor does a ray crossing a one-sided segment from its right. */
double hitDistance(const Shape& s, const Ray& ray);

/** Whether `ray` goes through shape number `index` (probability `s.pass_through`). */
bool passesThrough(const Shape& s, uint32_t index, const Ray& ray);

/** splitmix64 mixing: a well-spread 64-bit hash of `x`. */
uint64_t mix64(uint64_t x);

struct World
{
  Box bounds;
  std::vector<Shape> shapes;   ///< every shape lies inside `bounds`
  bool has_water = false;      ///< false: all land (forest)
  PolarCurve lake;             ///< water inside (if has_water)
  std::vector<PolarCurve> islands;  ///< land inside

  /** Adds `s` if it lies entirely inside the bounds; returns whether it was added. */
  bool add(const Shape& s);
  /** Whether a vehicle at `p` is on water (always false without water). */
  bool isWater(const Eigen::Vector2d& p) const;
};

/** Distance to the first shape the ray does not pass through, within `max_range`,
 * by testing every shape: the slow reference for ShapeGrid::cast. */
double castBruteForce(const World& world, const Ray& ray, double max_range);

}  // namespace swslam::sim
