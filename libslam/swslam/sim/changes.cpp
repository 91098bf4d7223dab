#include <swslam/sim/changes.h>

#include <swslam/common/atomic_file.h>

#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace swslam::sim
{
namespace
{
constexpr double kSmallestRemoved = 0.5;  // [m] radius: a rock taken away is a change of at least 1 m
constexpr double kClearance = 2.0;        // [m] between a rock put and any shape, and from the shore

double distanceToPath(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& samples)
{
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k + 1 < samples.size(); k++)
  {
    const Eigen::Vector2d a = samples[k], d = samples[k + 1] - a;
    const double u = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + u * d - p).norm());
  }
  return best;
}

bool inBand(const Eigen::Vector2d& p, const ChangesParams& c, const std::vector<Eigen::Vector2d>& samples)
{
  const double d = distanceToPath(p, samples);
  return d >= c.min_distance && d <= c.max_distance;
}

/** Whether a circle at `c` of radius `r` keeps kClearance from every shape and the shore. */
bool clear(const World& world, const Eigen::Vector2d& c, double r)
{
  if (!world.isWater(c) || world.lake.radialOffset(c) > -(r + kClearance)) return false;
  for (const auto& island : world.islands)
    if (island.radialOffset(c) < r + kClearance) return false;
  for (const Shape& s : world.shapes)
  {
    const Box b = boundingBox(s);
    const double dx = std::max({b.min_x - c.x(), 0.0, c.x() - b.max_x});
    const double dy = std::max({b.min_y - c.y(), 0.0, c.y() - b.max_y});
    if (std::hypot(dx, dy) < r + kClearance) return false;
  }
  return true;
}
}  // namespace

std::vector<WorldChange> applyChanges(World& world, const ChangesParams& p, const VehiclePath& path)
{
  std::vector<WorldChange> changes;
  if (!p.any()) return changes;
  std::mt19937_64 rng(mix64(p.seed ^ 0xC4A9ull));
  const auto& samples = path.samples();

  std::vector<size_t> candidates;
  for (size_t i = 0; i < world.shapes.size(); i++)
  {
    const Shape& s = world.shapes[i];
    if (s.kind == ShapeKind::Rock && s.radius >= kSmallestRemoved && inBand(s.a, p, samples)) candidates.push_back(i);
  }
  if (candidates.size() < p.remove)
    throw std::invalid_argument(mrpt::format("[changes] remove = %u, but only %zu rocks of radius >= %.1f m lie %.1f-%.1f m "
                                             "from the path",
                                             p.remove, candidates.size(), kSmallestRemoved, p.min_distance, p.max_distance));
  std::shuffle(candidates.begin(), candidates.end(), rng);
  candidates.resize(p.remove);
  std::sort(candidates.rbegin(), candidates.rend());  // erase from the back: indices stay valid
  for (const size_t i : candidates)
  {
    changes.push_back({false, world.shapes[i].a, world.shapes[i].radius});
    world.shapes.erase(world.shapes.begin() + static_cast<std::ptrdiff_t>(i));
  }

  std::uniform_real_distribution<double> ux(world.bounds.min_x, world.bounds.max_x), uy(world.bounds.min_y, world.bounds.max_y);
  for (unsigned k = 0; k < p.add; k++)
  {
    bool placed = false;
    for (int attempt = 0; attempt < 100000 && !placed; attempt++)
    {
      const Eigen::Vector2d c(ux(rng), uy(rng));
      if (!inBand(c, p, samples) || !clear(world, c, p.radius)) continue;
      // Not where a rock was taken away: that change would hide this one.
      bool apart = true;
      for (const WorldChange& ch : changes) apart = apart && (ch.center - c).norm() > ch.radius + p.radius + kClearance;
      if (!apart) continue;
      const Shape rock = Shape::circle(ShapeKind::Rock, c, p.radius);
      if (!world.add(rock)) continue;
      changes.push_back({true, c, p.radius});
      placed = true;
    }
    if (!placed)
      throw std::invalid_argument(mrpt::format("[changes] add: no free water for rock %u of radius %.2f m within %.1f-%.1f m "
                                               "of the path",
                                               k + 1, p.radius, p.min_distance, p.max_distance));
  }
  return changes;
}

void writeChanges(const std::string& path, const std::vector<WorldChange>& changes)
{
  std::string text = "kind,x,y,radius\n";
  for (const WorldChange& c : changes)
    text += mrpt::format("%s,%.4f,%.4f,%.4f\n", c.added ? "added" : "removed", c.center.x(), c.center.y(), c.radius);
  common::writeTextAtomically(path, text);
}

}  // namespace swslam::sim
