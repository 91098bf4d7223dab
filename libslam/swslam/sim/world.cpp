#include <swslam/sim/world.h>

#include <cmath>

namespace swslam::sim
{
Shape Shape::circle(ShapeKind kind, const Eigen::Vector2d& c, double r, double pass)
{
  Shape s;
  s.kind = kind;
  s.a = s.b = c;
  s.radius = r;
  s.pass_through = pass;
  return s;
}

Shape Shape::segment(ShapeKind kind, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  Shape s;
  s.kind = kind;
  s.a = a;
  s.b = b;
  return s;
}

Shape Shape::bank(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double pass)
{
  Shape s = segment(ShapeKind::Bank, a, b);
  s.pass_through = pass;
  s.one_sided = true;
  return s;
}

Box boundingBox(const Shape& s)
{
  if (s.isCircle())
    return {s.a.x() - s.radius, s.a.y() - s.radius, s.a.x() + s.radius, s.a.y() + s.radius};
  return {std::min(s.a.x(), s.b.x()), std::min(s.a.y(), s.b.y()), std::max(s.a.x(), s.b.x()),
          std::max(s.a.y(), s.b.y())};
}

double PolarCurve::radiusAt(double theta) const
{
  double r = radius;
  for (size_t i = 0; i < amplitudes.size(); i++)
    r += amplitudes[i] * std::cos(static_cast<double>(i + 2) * theta + phases[i]);
  return r;
}

double PolarCurve::radialOffset(const Eigen::Vector2d& p) const
{
  const Eigen::Vector2d d = p - center;
  return d.norm() - radiusAt(std::atan2(d.y(), d.x()));
}

double hitDistance(const Shape& s, const Ray& ray)
{
  const Eigen::Vector2d& d = ray.dir;
  if (s.isCircle())
  {
    // |o + t d - c|^2 = r^2 with |d| = 1: t = -b -+ sqrt(b^2 - c).
    const Eigen::Vector2d f = ray.origin - s.a;
    const double b = f.dot(d);
    const double disc = b * b - (f.squaredNorm() - s.radius * s.radius);
    if (disc < 0) return kNoHit;
    const double t = -b - std::sqrt(disc);
    return t > 0 ? t : kNoHit;
  }
  // o + t d = a + u (b - a), t > 0, u in [0, 1].
  const Eigen::Vector2d e = s.b - s.a;
  // den = d x e > 0: the ray comes from the left of a -> b.
  const double den = d.x() * e.y() - d.y() * e.x();
  if (std::abs(den) < 1e-15 || (s.one_sided && den < 0)) return kNoHit;
  const Eigen::Vector2d w = s.a - ray.origin;
  const double t = (w.x() * e.y() - w.y() * e.x()) / den;
  const double u = (w.x() * d.y() - w.y() * d.x()) / den;
  return (t > 0 && u >= 0 && u <= 1) ? t : kNoHit;
}

uint64_t mix64(uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

bool passesThrough(const Shape& s, uint32_t index, const Ray& ray)
{
  if (s.pass_through <= 0) return false;
  const uint64_t h = mix64(ray.key ^ mix64(index));
  const double u = static_cast<double>(h >> 11) * 0x1.0p-53;  // uniform in [0, 1)
  return u < s.pass_through;
}

bool World::add(const Shape& s)
{
  if (!bounds.contains(boundingBox(s))) return false;
  shapes.push_back(s);
  return true;
}

bool World::isWater(const Eigen::Vector2d& p) const
{
  if (!has_water || lake.radialOffset(p) >= 0) return false;
  for (const auto& island : islands)
    if (island.radialOffset(p) <= 0) return false;
  return true;
}

double castBruteForce(const World& world, const Ray& ray, double max_range)
{
  double best = kNoHit;
  for (size_t i = 0; i < world.shapes.size(); i++)
  {
    const double t = hitDistance(world.shapes[i], ray);
    if (t < best && !passesThrough(world.shapes[i], static_cast<uint32_t>(i), ray)) best = t;
  }
  return best <= max_range ? best : kNoHit;
}

}  // namespace swslam::sim
