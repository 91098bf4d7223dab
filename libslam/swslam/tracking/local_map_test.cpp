// The virtual scan of the local map against ray casting, occlusion, an empty map, and the
// z-buffer against every bin tried on every surface.
#include <swslam/tracking/local_map.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::tracking;
using mrpt::poses::CPose2D;

namespace
{
constexpr size_t kBeams = 361;
constexpr double kAperture = 1.5 * M_PI, kMaxRange = 30;

sensor::Scan scanOf(const test::World& world, const CPose2D& at, double sigma = 0, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  return sensor::scanFromObservation(test::simulateObservation(world, at, kBeams, kAperture, kMaxRange, sigma, rng));
}

/** Distance from p to the nearest wall or pillar of `w`. */
double distanceToWorld(const test::World& w, const Eigen::Vector2d& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : w.segments)
  {
    const Eigen::Vector2d a(s.x0, s.y0), b(s.x1, s.y1);
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  for (const auto& c : w.circles) best = std::min(best, std::abs((p - Eigen::Vector2d(c.cx, c.cy)).norm() - c.r));
  return best;
}

/** An empty box of 8 x 6 m: the keyframes inside see its walls at more than
 * kMinSurfaceAngle, as surfaces, so a virtual scan from anywhere inside is the ray-cast one. */
test::World box()
{
  test::World w;
  w.segments = {{-4, -3, 4, -3}, {4, -3, 4, 3}, {4, 3, -4, 3}, {-4, 3, -4, -3}};
  return w;
}
}  // namespace

TEST(LocalMap, VirtualScanOfAKnownRoomIsTheRayCastOne)
{
  const test::World w = box();
  const std::vector<CPose2D> at = {{-1, 0, 0}, {0, 0.5, 1.0}, {1, -0.5, -2.0}};
  std::vector<sensor::Scan> scans;
  for (const auto& p : at) scans.push_back(scanOf(w, p));
  std::vector<MapScan> map;
  for (size_t k = 0; k < at.size(); k++) map.push_back({at[k], &scans[k]});

  const CPose2D from(0.5, 0.3, 2.5);
  const sensor::Scan truth = scanOf(w, from);
  const sensor::Scan v = virtualScan(map, from, truth, 0.1);
  ASSERT_EQ(v.size(), truth.size());
  size_t compared = 0;
  for (size_t i = 0; i < v.size(); i++)
  {
    EXPECT_EQ(v.beam_index[i], truth.beam_index[i]);
    EXPECT_NEAR(v.angles[i], truth.angles[i], 1e-9);
    // Chords across a corner cut it; elsewhere the keyframes' points lie on the walls.
    const Eigen::Vector2d p = truth.points[i];
    const Eigen::Vector2d world_p(from.x() + std::cos(from.phi()) * p.x() - std::sin(from.phi()) * p.y(),
                                  from.y() + std::sin(from.phi()) * p.x() + std::cos(from.phi()) * p.y());
    if (std::abs(std::abs(world_p.x()) - 4) < 0.3 && std::abs(std::abs(world_p.y()) - 3) < 0.3) continue;
    EXPECT_NEAR(v.ranges[i], truth.ranges[i], 1e-6) << "ray " << i;
    compared++;
  }
  EXPECT_GT(compared, v.size() * 9 / 10);
  EXPECT_EQ(v.sensor_label, truth.sensor_label);
  EXPECT_EQ(v.beam_count, truth.beam_count);
}

TEST(LocalMap, AVirtualScanFromAKeyframeIsThatKeyframe)
{
  const test::World w = test::roomWorld();
  const CPose2D at(-1, 1, 0.3);
  const sensor::Scan s = scanOf(w, at, 0.01);
  const sensor::Scan v = virtualScan({{at, &s}}, at, s, 0.1);
  ASSERT_EQ(v.size(), s.size());
  for (size_t i = 0; i < v.size(); i++)
  {
    EXPECT_EQ(v.beam_index[i], s.beam_index[i]);
    // MRPT's ray directions are single precision.
    EXPECT_NEAR((v.points[i] - s.points[i]).norm(), 0, 1e-5) << "ray " << i;
  }
}

TEST(LocalMap, WallsHideWhatOtherKeyframesSawBehindThem)
{
  // A wall at x = 0 from y = -1 to 1, seen by keyframe A from the left; keyframe B, beyond it
  // on the right, sees the far wall at x = 5 there. From the left, the far wall behind the
  // short wall is hidden; beside it, it shows.
  test::World near_wall, far_wall;
  near_wall.segments = {{0, -1, 0, 1}};
  far_wall.segments = {{5, -10, 5, 10}};
  const CPose2D a(-2, 0, 0), b(3, 0, 0);
  const sensor::Scan sa = scanOf(near_wall, a), sb = scanOf(far_wall, b);
  const std::vector<MapScan> map = {{a, &sa}, {b, &sb}};
  const CPose2D from(-1.5, 0.2, 0);
  const sensor::Scan v = virtualScan(map, from, sa, 0.1);
  size_t hidden = 0, beside = 0;
  for (size_t i = 0; i < v.size(); i++)
  {
    const double x = from.x() + v.points[i].x(), y = from.y() + v.points[i].y();
    const double bearing_y_at_near = from.y() + 1.5 * std::tan(v.angles[i]);  // where the ray meets x = 0
    if (std::abs(v.angles[i]) < M_PI / 2 && std::abs(bearing_y_at_near) < 0.95)
    {
      EXPECT_NEAR(x, 0, 1e-6) << "ray " << i << " sees past the near wall";
      hidden++;
    }
    else if (std::abs(v.angles[i]) < M_PI / 2 && std::abs(bearing_y_at_near) > 1.05 && std::abs(y) < 9)
    {
      EXPECT_NEAR(x, 5, 1e-6) << "ray " << i;
      beside++;
    }
  }
  EXPECT_GT(hidden, 20u);
  EXPECT_GT(beside, 20u);
}

TEST(LocalMap, EdgeOnSegmentsAreNotSurfaces)
{
  // A post in front of a far wall: the rays from the post's edge to the wall are a depth jump,
  // not a wall, and must not hide the far wall from another viewpoint.
  test::World w;
  w.segments = {{4, -10, 4, 10}};
  w.circles = {{1, 0, 0.2}};
  const CPose2D at(0, 0, 0);
  const sensor::Scan s = scanOf(w, at);
  size_t jumps = 0;
  for (size_t i = 0; i + 1 < s.size(); i++)
    if (std::abs(s.ranges[i + 1] - s.ranges[i]) > 1)
    {
      EXPECT_FALSE(linkedRays(s, i)) << "ray " << i;
      jumps++;
    }
  EXPECT_EQ(jumps, 2u);
  // From the side, no ray sees a surface along a jump (the post's chords are within 2 mm of it).
  const CPose2D from(0, 1.5, 0);
  const sensor::Scan v = virtualScan({{at, &s}}, from, s, 0.1);
  for (size_t i = 0; i < v.size(); i++)
  {
    const Eigen::Vector2d p = v.points[i] + Eigen::Vector2d(from.x(), from.y());
    EXPECT_LT(distanceToWorld(w, p), 2e-3) << "ray " << i << " at " << p.transpose();
  }
}

TEST(LocalMap, AnEmptyMapGivesAnEmptyScan)
{
  const sensor::Scan like = scanOf(box(), CPose2D());
  const sensor::Scan v = virtualScan({}, CPose2D(1, 2, 3), like, 0.1);
  EXPECT_TRUE(v.empty());
  EXPECT_EQ(v.beam_count, like.beam_count);
  // A map out of reach (beyond the maximum range) too.
  const sensor::Scan far = virtualScan({{CPose2D(100, 0, 0), &like}}, CPose2D(), like, 0.1);
  EXPECT_TRUE(far.empty());
}

TEST(LocalMap, ZBufferEqualsTryingEveryBin)
{
  // Random cluttered worlds seen by a few keyframes (noisy), rendered from random poses by
  // sensors of several apertures, a full circle among them.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (unsigned trial = 0; trial < 20; trial++)
  {
    const test::World w = test::clutteredWorld(trial);
    std::vector<CPose2D> at;
    std::vector<sensor::Scan> scans;
    for (int k = 0; k < 4; k++)
    {
      at.emplace_back(3 * u(rng), 3 * u(rng), M_PI * u(rng));
      scans.push_back(scanOf(w, at.back(), 0.02, trial * 10 + k));
    }
    std::vector<MapScan> map;
    for (size_t k = 0; k < at.size(); k++) map.push_back({at[k], &scans[k]});
    const double aperture = trial % 3 == 0 ? 2 * M_PI * 359 / 360 : (trial % 3 == 1 ? M_PI : kAperture);
    std::mt19937 obs_rng(trial);
    const sensor::Scan like = sensor::scanFromObservation(
        test::simulateObservation(w, CPose2D(), trial % 3 == 0 ? 360 : 181, aperture, kMaxRange, 0, obs_rng));
    const CPose2D from(3 * u(rng), 3 * u(rng), M_PI * u(rng));
    const sensor::Scan fast = virtualScan(map, from, like, 0.1);
    const sensor::Scan slow = virtualScanBruteForce(map, from, like, 0.1);
    ASSERT_EQ(fast.size(), slow.size()) << "trial " << trial;
    ASSERT_GT(fast.size(), like.beam_count / 4) << "trial " << trial;
    for (size_t i = 0; i < fast.size(); i++)
    {
      EXPECT_EQ(fast.beam_index[i], slow.beam_index[i]) << "trial " << trial;
      EXPECT_NEAR(fast.ranges[i], slow.ranges[i], 1e-9) << "trial " << trial << " ray " << i;
      EXPECT_NEAR(fast.angles[i], slow.angles[i], 1e-9) << "trial " << trial << " ray " << i;
      if (i > 0) EXPECT_GE(fast.angles[i], fast.angles[i - 1]) << "trial " << trial;
    }
  }
}

TEST(LocalMap, AMatchMovesToAnotherReferenceFrameWithItsCovariance)
{
  plicp::MatchResult m;
  m.status = plicp::MatchStatus::Converged;
  m.pose = CPose2D(0.3, -0.1, 0.2);
  m.covariance << 4, 1, 0.5, 1, 2, 0.2, 0.5, 0.2, 1;
  const CPose2D frame(1, 2, 0.7);
  const plicp::MatchResult out = inReferenceFrame(m, frame);
  const CPose2D expected = frame + m.pose;
  EXPECT_NEAR((out.pose - expected).norm(), 0, 1e-12);
  // A small move d of the match moves the result by R d: the covariance follows.
  const double h = 1e-6;
  for (int j = 0; j < 3; j++)
  {
    CPose2D moved = m.pose;
    if (j == 0) moved.x(moved.x() + h);
    if (j == 1) moved.y(moved.y() + h);
    if (j == 2) moved.phi(moved.phi() + h);
    const CPose2D r = frame + moved;
    const Eigen::Vector3d col((r.x() - expected.x()) / h, (r.y() - expected.y()) / h, (r.phi() - expected.phi()) / h);
    Eigen::Matrix3d jac = Eigen::Matrix3d::Identity();
    jac.topLeftCorner<2, 2>() << std::cos(0.7), -std::sin(0.7), std::sin(0.7), std::cos(0.7);
    EXPECT_NEAR((col - jac.col(j)).norm(), 0, 1e-5);
  }
  Eigen::Matrix3d jac = Eigen::Matrix3d::Identity();
  jac.topLeftCorner<2, 2>() << std::cos(0.7), -std::sin(0.7), std::sin(0.7), std::cos(0.7);
  EXPECT_NEAR((out.covariance - jac * m.covariance * jac.transpose()).norm(), 0, 1e-12);
}
