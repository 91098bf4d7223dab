// A second peak of the correlative objective: a symmetric room has one, a room with a jog and
// pillars has none within the margin; the exclusion search equals brute force.
#include <swslam/correlative/peaks.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::correlative;

namespace
{
/** Points every 2 cm along the world's segments: the reference's surfaces. */
std::vector<Eigen::Vector2d> wallPoints(const test::World& w)
{
  std::vector<Eigen::Vector2d> out;
  for (const auto& s : w.segments)
  {
    const Eigen::Vector2d a(s.x0, s.y0), b(s.x1, s.y1);
    const int n = static_cast<int>((b - a).norm() / 0.02);
    for (int k = 0; k <= n; k++) out.push_back(a + (b - a) * k / std::max(n, 1));
  }
  return out;
}

struct PeakScene
{
  ScorePyramid pyramid;
  std::vector<Eigen::Vector2d> points;
  SearchWindow window;
};

/** The scan a full-circle sensor at (1, 0.3, 0) takes in `world`, thinned, against a grid of
 * the world's walls; the window (3 m, the whole circle) is centred on the true pose. */
PeakScene peakScene(const test::World& world)
{
  std::mt19937 rng(2);
  const auto obs = test::simulateObservation(world, mrpt::poses::CPose2D(1, 0.3, 0), 360, 2 * M_PI, 30, 0.01, rng);
  const double res = 0.1;
  const int depth = depthForWindow(3.0, res);
  SearchWindow w;
  w.centre = Eigen::Vector3d(1, 0.3, 0);
  w.half_xy = 3.0;
  w.half_theta = M_PI;
  w.theta_step = 2.0 * M_PI / 180;
  w.cost_per_m = 0.002;
  return {ScorePyramid(buildScoreGrid(wallPoints(world), res, 0.1, (1 << depth) - 1), depth),
          thinPoints(sensor::scanFromObservation(obs).points, res, 30), w};
}
}  // namespace

TEST(CorrelativePeaks, ASymmetricRoomHasTwoSimilarPeaksFarApart)
{
  test::World room;  // 12 x 6 m, symmetric about both axes
  room.segments = {{-6, -3, 6, -3}, {6, -3, 6, 3}, {6, 3, -6, 3}, {-6, 3, -6, -3}};
  const PeakScene s = peakScene(room);
  const Eigen::Vector3d truth(1, 0.3, 0);
  const auto p = secondPeak(s.pyramid, s.points, s.window, truth, peakRadius(0.1, 0.1), 0.1, 0.02);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->similar) << p->peak.objective << " vs " << p->chosen_objective;
  // The room turned by pi about its centre is itself: the sensor at (-1, -0.3) turned by pi
  // sees the same scan.
  EXPECT_GT((p->peak.pose.head<2>() - truth.head<2>()).norm(), 1.0);
  EXPECT_NEAR(std::abs(std::remainder(p->peak.pose.z(), 2 * M_PI)), M_PI, 0.05);
  // The exclusion search is exact: brute force over the same window finds the same objective.
  SearchWindow w = s.window;
  w.exclude_xy = truth.head<2>();
  w.exclude_radius = peakRadius(0.1, 0.1);
  const auto brute = searchBruteForce(s.pyramid.levels.front(), s.points, w, 0.1);
  ASSERT_TRUE(brute);
  EXPECT_NEAR(brute->objective, p->peak.objective, 1e-9);
}

TEST(CorrelativePeaks, ARoomWithAJogAndPillarsHasOnePeak)
{
  const test::World room = test::roomWorld();
  const PeakScene s = peakScene(room);
  const auto p = secondPeak(s.pyramid, s.points, s.window, Eigen::Vector3d(1, 0.3, 0), peakRadius(0.1, 0.1), 0.1, 0.02);
  if (p) EXPECT_FALSE(p->similar) << p->peak.objective << " vs " << p->chosen_objective;
}

TEST(CorrelativePeaks, NoPointsNoPeak)
{
  const PeakScene s = peakScene(test::roomWorld());
  EXPECT_FALSE(secondPeak(s.pyramid, {}, s.window, Eigen::Vector3d(1, 0.3, 0), 0.4, 0.1, 0.02));
}
