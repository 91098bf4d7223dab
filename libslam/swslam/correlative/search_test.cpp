// The correlative search: score grid, pyramid and branch and bound against brute force.
#include <swslam/correlative/search.h>
#include <swslam/correlative/search_setup.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::correlative;

namespace
{
std::vector<Eigen::Vector2d> randomPoints(std::mt19937& rng, size_t n, double half)
{
  std::uniform_real_distribution<double> U(-half, half);
  std::vector<Eigen::Vector2d> pts;
  for (size_t k = 0; k < n; k++) pts.emplace_back(U(rng), U(rng));
  return pts;
}

std::vector<Eigen::Vector2d> pointsOf(const test::World& world, const mrpt::poses::CPose2D& pose,
                                      std::mt19937& rng)
{
  return sensor::scanFromObservation(test::simulateObservation(world, pose, 361, M_PI, 30, 0.02, rng)).points;
}

Eigen::Vector3d vec(const mrpt::poses::CPose2D& p) { return {p.x(), p.y(), p.phi()}; }
}  // namespace

TEST(CorrelativeGrid, CellsAreTheKernelOfTheNearestPoint)
{
  std::mt19937 rng(3);
  const auto pts = randomPoints(rng, 40, 2.0);
  const double res = 0.07, sigma = 0.12;
  const ScoreGrid g = buildScoreGrid(pts, res, sigma, 2);
  ASSERT_GT(g.width, 0);
  for (const auto& p : pts) EXPECT_GT(g.at(g.cellOf(p).x(), g.cellOf(p).y()), 0);
  for (int y = 0; y < g.height; y++)
    for (int x = 0; x < g.width; x++)
    {
      const Eigen::Vector2d centre = g.origin + (Eigen::Vector2d(x, y).array() + 0.5).matrix() * res;
      double d2 = 1e300;
      for (const auto& p : pts) d2 = std::min(d2, (centre - p).squaredNorm());
      const int expected = d2 > 9 * sigma * sigma ? 0 : static_cast<int>(std::lround(255 * std::exp(-d2 / (2 * sigma * sigma))));
      ASSERT_EQ(g.at(x, y), expected) << "cell " << x << ", " << y;
    }
  EXPECT_TRUE(buildScoreGrid({}, res, sigma).cells.empty());
  EXPECT_THROW(buildScoreGrid(pts, 0, sigma), std::invalid_argument);
}

TEST(CorrelativeGrid, TheGridHoldsTheRaysOriginsAndPadsOnlyItsLowSides)
{
  const double res = 0.1, sigma = 0.1;
  const std::vector<Eigen::Vector2d> hits = {{10.03, 0.04}, {10.03, 1.04}, {10.03, 2.04}};
  const ScoreGrid plain = buildScoreGrid(hits, res, sigma, 7);
  // The kernel's reach on every side, 7 cells of padding on the low sides only.
  const int reach = static_cast<int>(std::ceil(3 * sigma / res));
  EXPECT_NEAR(plain.origin.x(), hits.front().x() - (7 + reach) * res, 1e-9);
  EXPECT_NEAR(plain.origin.y(), hits.front().y() - (7 + reach) * res, 1e-9);
  EXPECT_EQ(plain.width, plain.cellOf(hits.back()).x() + reach + 1);
  EXPECT_EQ(plain.height, plain.cellOf(hits.back()).y() + reach + 1);
  // A sensor 10 m from its hits (beyond reach and padding): the grid grows by whole cells to
  // hold it, its cells stay where they were, and the free space reaches the sensor.
  ScoreGrid grid = buildScoreGrid(hits, res, sigma, 7, {{0, 1}, {Eigen::Vector2d::Constant(NAN)}});
  EXPECT_EQ(grid.height, plain.height);
  EXPECT_EQ(grid.width, plain.width - plain.cellOf({0, 1}).x());
  EXPECT_EQ(grid.cellOf({0, 1}).x(), 0);
  for (const auto& p : hits)
    EXPECT_EQ(grid.at(grid.cellOf(p).x(), grid.cellOf(p).y()), plain.at(plain.cellOf(p).x(), plain.cellOf(p).y()));
  std::vector<Ray> rays;
  for (const auto& p : hits) rays.push_back({{0, 1}, p});
  markFreeSpace(grid, rays, -200);
  const Eigen::Vector2i near_sensor = grid.cellOf({0.3, 1.0});
  EXPECT_EQ(grid.at(near_sensor.x(), near_sensor.y()), -200);
  const ScorePyramid pyr(grid, 3);
  EXPECT_EQ(pyr.levels[3].width, grid.width);
}

TEST(CorrelativeGrid, PyramidLevelsAreWindowMaxima)
{
  std::mt19937 rng(5);
  const ScorePyramid pyr(buildScoreGrid(randomPoints(rng, 30, 1.5), 0.1, 0.1, 7), 3);
  ASSERT_EQ(pyr.depth(), 3);
  const ScoreGrid& base = pyr.levels[0];
  for (int h = 1; h <= 3; h++)
    for (int y = 0; y < base.height; y++)
      for (int x = 0; x < base.width; x++)
      {
        int m = 0;
        for (int dy = 0; dy < (1 << h); dy++)
          for (int dx = 0; dx < (1 << h); dx++) m = std::max(m, base.at(x + dx, y + dy));
        ASSERT_EQ(pyr.levels[h].at(x, y), m) << "level " << h << " cell " << x << ", " << y;
      }
  // Too little padding for the depth: a window could start outside the grid and miss data.
  EXPECT_THROW(ScorePyramid(buildScoreGrid(randomPoints(rng, 5, 1), 0.1, 0.1, 6), 3), std::invalid_argument);
}

TEST(CorrelativeGrid, PyramidBoundsHoldWhereFreeSpaceReachesTheGridsEdge)
{
  // Free space in the padding (a submap ray whose origin lies beyond the hits): a window
  // that sticks out of the grid has a partner scoring 0 (ScoreGrid::at), above the free
  // cells, and its level value must not fall below that, or branch and bound prunes wrongly.
  std::mt19937 rng(8);
  ScoreGrid grid = buildScoreGrid(randomPoints(rng, 20, 1.0), 0.1, 0.1, 3);
  for (auto& c : grid.cells)
    if (c == 0) c = -255;
  const ScorePyramid pyr(grid, 2);
  for (int h = 1; h <= 2; h++)
    for (int y = 0; y < grid.height; y++)
      for (int x = 0; x < grid.width; x++)
      {
        int m = std::numeric_limits<int>::min();
        for (int dy = 0; dy < (1 << h); dy++)
          for (int dx = 0; dx < (1 << h); dx++) m = std::max(m, grid.at(x + dx, y + dy));
        ASSERT_EQ(pyr.levels[h].at(x, y), m) << "level " << h << " cell " << x << ", " << y;
      }
}

TEST(CorrelativeSearch, BranchAndBoundEqualsBruteForce)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  const auto world = test::clutteredWorld(2);
  for (int trial = 0; trial < 6; trial++)
  {
    const mrpt::poses::CPose2D a(2 * U(rng), -2 + U(rng), U(rng));
    const mrpt::poses::CPose2D motion(1.0 * U(rng), 1.0 * U(rng), 1.2 * U(rng));
    const auto ref = thinPoints(pointsOf(world, a, rng), 0.1, 20);
    const auto cur = thinPoints(pointsOf(world, a + motion, rng), 0.1, 20);
    SearchWindow w;
    w.half_xy = trial % 2 ? 0.75 : 1.2;
    w.half_theta = trial % 3 == 0 ? M_PI : 0.6;
    w.theta_step = 3 * M_PI / 180;
    w.centre = Eigen::Vector3d(0.3 * U(rng), 0.3 * U(rng), 0.2 * U(rng));
    // With and without a motion prior (costs in score units per metre and radian).
    w.cost_per_m = trial < 3 ? 0.0 : 0.1;
    w.cost_per_rad = trial < 3 ? 0.0 : 0.05 * (trial - 2);
    w.cost_per_m2 = trial == 2 || trial == 5 ? 0.08 : 0.0;  // the steady-motion prior's quadratic cost
    const double res = trial % 2 ? 0.1 : 0.15;
    const int depth = depthForWindow(w.half_xy, res) - trial % 2;  // full and shallower pyramids
    ScoreGrid grid = buildScoreGrid(ref, res, 0.15, (1 << depth) - 1);
    if (trial % 2 == 0)  // negative cells too: the reference's free space
    {
      std::vector<Ray> rays;
      for (const auto& p : ref) rays.push_back({Eigen::Vector2d::Zero(), p});
      markFreeSpace(grid, rays, -200);
    }
    const ScorePyramid pyr(std::move(grid), depth);
    for (double min_score : {0.0, 0.3, 0.99})
    {
      const auto fast = searchBranchAndBound(pyr, cur, w, min_score);
      const auto slow = searchBruteForce(pyr.levels[0], cur, w, min_score);
      ASSERT_EQ(fast.has_value(), slow.has_value()) << "trial " << trial << " min " << min_score;
      if (!slow) continue;
      EXPECT_EQ(fast->objective, slow->objective) << "trial " << trial;
      EXPECT_GE(fast->score, min_score);
      EXPECT_NEAR(objective(w, fast->score, fast->pose), fast->objective, 1e-12);
      EXPECT_LT(fast->bounds_evaluated, slow->bounds_evaluated / 4) << "trial " << trial;
      // Per level: the top level scores every angle's blocks, each level below only the
      // children of the blocks split above it (up to four each, fewer at the window's edge).
      const int top = static_cast<int>(fast->evaluated_by_level.size()) - 1;
      ASSERT_EQ(top, depth);
      ASSERT_EQ(fast->expanded_by_level.size(), fast->evaluated_by_level.size());
      const int n = static_cast<int>(std::floor(w.half_xy / res + 1e-9)), blocks = (2 * n + (1 << top)) >> top;
      EXPECT_EQ(fast->evaluated_by_level[top], windowAngles(w).size() * blocks * blocks) << "trial " << trial;
      size_t total = 0;
      for (int h = 0; h <= top; h++)
      {
        total += fast->evaluated_by_level[h];
        EXPECT_LE(fast->expanded_by_level[h], fast->evaluated_by_level[h]);
        if (h == 0) EXPECT_EQ(fast->expanded_by_level[h], 0u);
        if (h == top) continue;
        EXPECT_LE(fast->evaluated_by_level[h], 4 * fast->expanded_by_level[h + 1]) << "trial " << trial;
        EXPECT_GE(fast->evaluated_by_level[h], fast->expanded_by_level[h + 1]) << "trial " << trial;
      }
      EXPECT_EQ(total, fast->bounds_evaluated);
      // The reported pose is on the lattice and scores what was reported.
      const Eigen::Vector2d cells = (fast->pose.head<2>() - w.centre.head<2>()) / res;
      EXPECT_NEAR(cells.x(), std::round(cells.x()), 1e-9);
      EXPECT_LE(std::abs(cells.x()), w.half_xy / res + 1e-9);
      EXPECT_NEAR(scoreAt(pyr.levels[0], cur, fast->pose), fast->score, 0.02);

      // A floor on the objective: just below the best it changes nothing, at the best there is
      // no result, and in between it agrees with the brute force under the same floor.
      const auto below = searchBranchAndBound(pyr, cur, w, min_score, slow->objective - 1e-9);
      ASSERT_TRUE(below.has_value());
      EXPECT_EQ(below->objective, slow->objective);
      EXPECT_LE(below->bounds_evaluated, fast->bounds_evaluated);
      EXPECT_FALSE(searchBranchAndBound(pyr, cur, w, min_score, slow->objective).has_value());
      EXPECT_FALSE(searchBruteForce(pyr.levels[0], cur, w, min_score, slow->objective).has_value());
      const double mid = slow->objective - 0.05;
      const auto fast_mid = searchBranchAndBound(pyr, cur, w, min_score, mid);
      const auto slow_mid = searchBruteForce(pyr.levels[0], cur, w, min_score, mid);
      ASSERT_EQ(fast_mid.has_value(), slow_mid.has_value());
      if (slow_mid) EXPECT_EQ(fast_mid->objective, slow_mid->objective);

      // The best pose elsewhere (a disc around the best excluded): same in both, outside the
      // disc, and no better than the best.
      SearchWindow elsewhere = w;
      elsewhere.exclude_xy = fast->pose.head<2>();
      elsewhere.exclude_radius = 0.35;
      const auto fast2 = searchBranchAndBound(pyr, cur, elsewhere, min_score);
      const auto slow2 = searchBruteForce(pyr.levels[0], cur, elsewhere, min_score);
      ASSERT_EQ(fast2.has_value(), slow2.has_value()) << "trial " << trial << " min " << min_score;
      if (!slow2) continue;
      EXPECT_EQ(fast2->objective, slow2->objective) << "trial " << trial;
      EXPECT_GT((fast2->pose.head<2>() - fast->pose.head<2>()).norm(), 0.35);
      EXPECT_FALSE(excluded(elsewhere, fast2->pose.head<2>()));
      EXPECT_LE(fast2->objective, fast->objective);
    }
  }
}

TEST(CorrelativeGrid, FreeSpaceMarksTheCellsARayCrossesBeforeItsHit)
{
  const double res = 0.1, sigma = 0.1;
  ScoreGrid g = buildScoreGrid({{2.0, 0.05}}, res, sigma, 30);
  const ScoreGrid before = g;
  markFreeSpace(g, {{{0.0, 0.05}, {2.0, 0.05}}}, -255);
  auto at = [&](const ScoreGrid& grid, double x, double y) {
    const Eigen::Vector2i c = grid.cellOf({x, y});
    return grid.at(c.x(), c.y());
  };
  for (double x = 0.05; x < 1.65; x += 0.1) EXPECT_EQ(at(g, x, 0.05), -255) << "x " << x;
  for (double x = 1.75; x < 2.35; x += 0.1)  // within the hit's kernel: unchanged
    EXPECT_EQ(at(g, x, 0.05), at(before, x, 0.05)) << "x " << x;
  EXPECT_GT(at(g, 2.0, 0.05), 150);  // the hit's cell: its centre is 0.07 m away
  EXPECT_EQ(at(g, 2.6, 0.05), 0);   // beyond the hit: unknown
  EXPECT_EQ(at(g, 1.0, 1.05), 0);   // beside the ray: unknown
  EXPECT_THROW(markFreeSpace(g, {}, 1), std::invalid_argument);
}

TEST(CorrelativeGrid, FreeSpaceAgreesWithAPerPointVersion)
{
  // markFreeSpace works in cell units; the slow version places each sample and asks cellOf.
  std::mt19937 rng(11);
  const double res = 0.1, sigma = 0.1;
  const auto hits = randomPoints(rng, 60, 6.0);
  std::vector<Ray> rays;
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const auto& h : hits) rays.push_back({Eigen::Vector2d(U(rng), U(rng)), h});
  rays.push_back({Eigen::Vector2d(20.0, 20.0), Eigen::Vector2d(25.0, -30.0)});  // mostly off the grid
  rays.push_back({hits.front(), hits.front()});                                  // no length
  ScoreGrid fast = buildScoreGrid(hits, res, sigma, 4);
  ScoreGrid slow = fast;
  markFreeSpace(fast, rays, -200);
  for (const Ray& r : rays)
  {
    const double length = (r.hit - r.origin).norm();
    if (!(length > 0)) continue;
    const Eigen::Vector2d u = (r.hit - r.origin) / length;
    for (double s = 0; s < length; s += res / 2)
    {
      const Eigen::Vector2i c = slow.cellOf(r.origin + s * u);
      if (slow.at(c.x(), c.y()) != 0 || c.x() < 0 || c.y() < 0 || c.x() >= slow.width || c.y() >= slow.height)
        continue;
      slow.cells[static_cast<size_t>(c.y()) * slow.width + c.x()] = -200;
    }
  }
  size_t marked = 0;
  for (size_t k = 0; k < fast.cells.size(); k++)
  {
    ASSERT_EQ(fast.cells[k], slow.cells[k]) << "cell " << k % fast.width << ", " << k / fast.width;
    marked += fast.cells[k] == -200;
  }
  EXPECT_GT(marked, 500u);
}

TEST(CorrelativeSearch, TheMotionPriorPicksTheAlignmentNearestThePrediction)
{
  // Two long parallel walls: every shift along them scores the same (a corridor).
  std::vector<Eigen::Vector2d> ref, cur;
  for (double x = -10; x <= 10; x += 0.05)
  {
    ref.emplace_back(x, 1.0);
    ref.emplace_back(x, -1.0);
    if (std::abs(x) < 3)
    {
      cur.emplace_back(x, 1.0);
      cur.emplace_back(x, -1.0);
    }
  }
  SearchWindow w;
  w.centre = {0.7, 0.0, 0.0};
  w.half_xy = 1.0;
  w.half_theta = 0.1;
  w.theta_step = 0.01;
  w.cost_per_m = 0.05;
  w.cost_per_rad = 0.05;
  const double res = 0.1;
  const int depth = depthForWindow(w.half_xy, res);
  const ScorePyramid pyr(buildScoreGrid(ref, res, 0.1, (1 << depth) - 1), depth);
  const auto r = searchBranchAndBound(pyr, cur, w, 0.5);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->pose.x(), 0.7, 1e-9);
  EXPECT_NEAR(r->pose.y(), 0.0, 1e-9);
  EXPECT_NEAR(r->pose.z(), 0.0, 1e-9);
  EXPECT_NEAR(r->objective, r->score, 1e-12);  // at the centre: no cost
}

TEST(CorrelativeSearch, FindsALargeTurnAndShiftFromIdentity)
{
  std::mt19937 rng(7);
  const auto world = test::roomWorld();
  const mrpt::poses::CPose2D a(-3, 1, 0.4), motion(1.1, -0.9, 80 * M_PI / 180);
  const auto ref = thinPoints(pointsOf(world, a, rng), 0.05, 30);
  const auto cur = thinPoints(pointsOf(world, a + motion, rng), 0.05, 30);
  SearchWindow w;  // identity centre, +-2 m, the whole circle in 1 deg steps
  const double res = 0.05;
  const int depth = depthForWindow(w.half_xy, res);
  const ScorePyramid pyr(buildScoreGrid(ref, res, 0.1, (1 << depth) - 1), depth);
  const auto r = searchBranchAndBound(pyr, cur, w, 0.3);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->pose.x(), motion.x(), 0.1);
  EXPECT_NEAR(r->pose.y(), motion.y(), 0.1);
  EXPECT_NEAR(std::remainder(r->pose.z() - motion.phi(), 2 * M_PI), 0, 1.5 * M_PI / 180);
  EXPECT_GT(r->score, scoreAt(pyr.levels[0], cur, Eigen::Vector3d::Zero()) + 0.3);
  EXPECT_GE(r->score, scoreAt(pyr.levels[0], cur, vec(motion)) - 0.05);
}

TEST(CorrelativeSearch, WindowAnglesCoverTheCircleOnce)
{
  SearchWindow w;
  w.centre.z() = 0.5;
  w.theta_step = 7 * M_PI / 180;  // does not divide 360: the step shrinks to 360 / 52
  const auto full = windowAngles(w);
  ASSERT_EQ(full.size(), 52u);
  EXPECT_NEAR(full.back() - full.front(), 2 * M_PI * 51 / 52, 1e-12);
  w.half_theta = 20 * M_PI / 180;
  const auto part = windowAngles(w);
  ASSERT_EQ(part.size(), 5u);
  EXPECT_NEAR(part.front(), 0.5 - 14 * M_PI / 180, 1e-12);
  EXPECT_EQ(depthForWindow(2.0, 0.1), 6);  // 41 offsets need a window of 64
  EXPECT_EQ(depthForWindow(0.0, 0.1), 0);
}

TEST(CorrelativeSearch, ThinPointsDropsFarAndCrowdedPoints)
{
  const std::vector<Eigen::Vector2d> pts = {{1, 0}, {1.02, 0}, {1.2, 0}, {50, 0}, {1.3, 0}};
  const auto kept = thinPoints(pts, 0.1, 30);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[1], Eigen::Vector2d(1.2, 0));
  EXPECT_EQ(kept[2], Eigen::Vector2d(1.3, 0));
}

TEST(CorrelativeSearch, NothingAboveTheMinimumScoreGivesNoResult)
{
  std::mt19937 rng(1);
  const auto world = test::roomWorld();
  const auto ref = thinPoints(pointsOf(world, mrpt::poses::CPose2D(0, 0, 0), rng), 0.1, 30);
  const ScorePyramid pyr(buildScoreGrid(ref, 0.1, 0.1, 1), 1);
  SearchWindow w;
  w.half_xy = 0.1;
  w.half_theta = 0.05;
  // Points far from every reference point score 0 everywhere in the window.
  EXPECT_FALSE(searchBranchAndBound(pyr, {{100, 100}, {101, 100}}, w, 0.0).has_value());
  EXPECT_FALSE(searchBranchAndBound(pyr, {}, w, 0.0).has_value());
  EXPECT_FALSE(searchBruteForce(pyr.levels[0], {{100, 100}}, w, 0.0).has_value());
}

TEST(CorrelativeSearch, ScoreAtAgreesWithAPerPointVersion)
{
  // The search's cells of turned points (their own floor) against ScoreGrid::cellOf: a grid of
  // random values, points inside it, just outside its low edges (where truncating instead of
  // flooring would land in cell 0) and far outside.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> U(-1, 1);
  std::uniform_int_distribution<int> V(-255, 255);
  ScoreGrid grid;
  grid.origin = {-1.05, -0.95};
  grid.resolution = 0.1;
  grid.width = 25;
  grid.height = 18;
  for (int k = 0; k < grid.width * grid.height; k++) grid.cells.push_back(static_cast<int16_t>(V(rng)));
  std::vector<Eigen::Vector2d> cur;
  for (int k = 0; k < 60; k++) cur.emplace_back(1.5 * U(rng), 1.5 * U(rng));
  for (int trial = 0; trial < 50; trial++)
  {
    const Eigen::Vector3d pose = trial == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(U(rng), U(rng), 3 * U(rng));
    const double c = std::cos(pose.z()), s = std::sin(pose.z());
    double sum = 0;
    size_t below_edge = 0;
    for (const auto& p : cur)
    {
      const Eigen::Vector2d q(c * p.x() - s * p.y() + pose.x(), s * p.x() + c * p.y() + pose.y());
      const Eigen::Vector2i cell = grid.cellOf(q);
      sum += grid.at(cell.x(), cell.y());
      below_edge += cell.x() == -1 || cell.y() == -1;
    }
    EXPECT_EQ(scoreAt(grid, cur, pose), sum / (255.0 * cur.size())) << "trial " << trial;
    if (trial == 0) EXPECT_GT(below_edge, 0u);
  }
}

TEST(CorrelativeSearch, CommonScoresAgreeWithAPerPointVersion)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  const auto world = test::clutteredWorld(4);
  for (int trial = 0; trial < 6; trial++)
  {
    const double ratio = trial % 2 ? 0.25 : 2.0;  // 2: no surface goes on
    const mrpt::poses::CPose2D a(U(rng), U(rng), 0.3 * U(rng));
    const auto ref = pointsOf(world, mrpt::poses::CPose2D(0, 0, 0), rng);
    const auto cur = thinPoints(pointsOf(world, a, rng), 0.1, 30);
    ScoreGrid grid = buildScoreGrid(ref, 0.1, 0.1, 2);
    std::vector<Ray> rays;
    for (const auto& p : ref) rays.push_back({Eigen::Vector2d::Zero(), p});
    markFreeSpace(grid, rays, -255);
    // The right pose and one 1.5 m and 20 deg off: some points fall in unseen or free cells.
    const Eigen::Vector3d pa = vec(a), pb = vec(a + mrpt::poses::CPose2D(1.5, -0.5, 0.35));
    const CommonScores c = commonScores(grid, cur, pa, pb, ratio);
    // Per point, by each pose's own transform.
    auto cellAt = [&](const Eigen::Vector3d& q, const Eigen::Vector2d& p) {
      double gx = 0, gy = 0;
      mrpt::poses::CPose2D(q.x(), q.y(), q.z()).composePoint(p.x(), p.y(), gx, gy);
      return grid.cellOf({gx, gy});
    };
    size_t n = 0, one_sided = 0, left_out = 0;
    double sa = 0, sb = 0;
    for (const auto& p : cur)
    {
      const Eigen::Vector2i ka = cellAt(pa, p), kb = cellAt(pb, p);
      const int va = grid.at(ka.x(), ka.y()), vb = grid.at(kb.x(), kb.y());
      if (va == 0 && vb == 0) continue;
      if (va == 0 || vb == 0)
      {
        one_sided++;
        const Eigen::Vector2i known = va ? ka : kb, other = va ? kb : ka, beyond = known + (known - other);
        const int v = va ? va : vb;
        if (v > 0 && grid.at(beyond.x(), beyond.y()) >= ratio * v)
        {
          left_out++;
          continue;
        }
      }
      sa += va;
      sb += vb;
      n++;
    }
    EXPECT_GT(one_sided, 0u) << "trial " << trial;  // the case the function is for
    if (ratio > 1) EXPECT_EQ(left_out, 0u);
    ASSERT_EQ(c.points, n) << "trial " << trial;
    ASSERT_GT(n, 0u);
    EXPECT_NEAR(c.a, sa / (255.0 * n), 1e-12);
    EXPECT_NEAR(c.b, sb / (255.0 * n), 1e-12);
  }
  // Every point known at both poses: the plain scores.
  const auto ref = thinPoints(pointsOf(test::roomWorld(), mrpt::poses::CPose2D(0, 0, 0), rng), 0.1, 30);
  const ScoreGrid grid = buildScoreGrid(ref, 0.1, 0.1, 2);
  const CommonScores same = commonScores(grid, ref, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.25);
  EXPECT_EQ(same.points, ref.size());
  EXPECT_NEAR(same.a, scoreAt(grid, ref, Eigen::Vector3d::Zero()), 1e-12);
  // No point known at either pose: no points, scores 0.
  const CommonScores none = commonScores(grid, {{500, 500}}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.25);
  EXPECT_EQ(none.points, 0u);
  EXPECT_EQ(none.a, 0.0);
  EXPECT_EQ(commonScores(grid, {}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.25).points, 0u);
}

TEST(CorrelativeSearch, CommonScoresLeaveOutWhatASurfaceGoingOnWouldSupportAtEitherPose)
{
  // A wall seen from x = 0 to 5 m at y = 1 (a hit every 5 cm) and a post at (2, -1); the
  // second pose is 1 m back along the wall.
  std::vector<Eigen::Vector2d> ref;
  for (int k = 0; k <= 100; k++) ref.emplace_back(0.05 * k, 1);
  ref.emplace_back(2, -1);
  const ScoreGrid grid = buildScoreGrid(ref, 0.1, 0.1, 2);
  const Eigen::Vector3d here(0, 0, 0), back(-1, 0, 0);
  // On the wall near where it was last seen: unseen from the pose 1 m back, and the wall goes
  // on past it: left out.
  EXPECT_EQ(commonScores(grid, {{0.2, 1}}, here, back, 0.25).points, 0u);
  // The post: unseen from the pose 1 m back, and nothing beyond it: kept, for the first pose.
  const CommonScores post = commonScores(grid, {{2, -1}}, here, back, 0.25);
  EXPECT_EQ(post.points, 1u);
  EXPECT_GT(post.a, 0.7);
  EXPECT_EQ(post.b, 0.0);
  // Mid-wall, known at both poses: kept, about the same at both.
  const CommonScores mid = commonScores(grid, {{3, 1}}, here, back, 0.25);
  EXPECT_EQ(mid.points, 1u);
  EXPECT_NEAR(mid.a, mid.b, 0.05);
  // With a ratio above 1 no surface goes on: the wall's point counts too.
  EXPECT_EQ(commonScores(grid, {{0.2, 1}}, here, back, 2.0).points, 1u);
}

TEST(CorrelativeSearch, ScanRaysStartAtTheSensorAndStopAtMaxRange)
{
  sensor::Scan s;
  s.points = {{1, 0}, {0, 5}, {-3, 4}};
  const auto rays = scanRays(s, 4.5);
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_EQ(rays[0].origin, Eigen::Vector2d::Zero());
  EXPECT_EQ(rays[0].hit, Eigen::Vector2d(1, 0));
  EXPECT_EQ(scanRays(s, 5.0).size(), 3u);
}

TEST(CorrelativeGrid, ExtremeCoordinatesNeitherWriteOutsideTheGridNorAllocatePastTheBudget)
{
  // A scan mounted at x = 1e30 put a keyframe's rays there: the grid's size and cells came
  // from int conversions out of range, and buildScoreGrid wrote before its cells (threaded
  // swslam: heap corruption). Sizes are now computed in double and checked, writes clipped.
  const double res = 0.1, sigma = 0.1;
  const int pad = 63;  // the default window's pyramid (depth 6)
  const std::vector<Eigen::Vector2d> far = {{1e30, 0}, {1e30, 1e30}, {-1e30, 5}};
  for (const Eigen::Vector2d& at : far)
  {
    // Hits that far, together: a small grid there (1e30 + 5 m is 1e30 in double), whole.
    const std::vector<Eigen::Vector2d> hits = {at, at + Eigen::Vector2d(5, 0), at + Eigen::Vector2d(0, 3)};
    ScoreGrid g = buildScoreGrid(hits, res, sigma, pad, {at});
    ASSERT_GT(g.width, 0);
    EXPECT_LE(g.width, pad + 2 * 3 + 2) << at.transpose();
    EXPECT_EQ(g.cells.size(), static_cast<size_t>(g.width) * g.height);
    markFreeSpace(g, {{at, at + Eigen::Vector2d(5, 0)}, {Eigen::Vector2d::Zero(), at}}, -255);
    const ScorePyramid pyr(g, 6);
    // A scan near the origin, searched around the origin and around the far place: no match,
    // and every cell looked up through cellFloor's clamp.
    std::mt19937 rng(1);
    const auto pts = randomPoints(rng, 50, 5.0);
    SearchWindow w;
    w.half_xy = 3.0;
    EXPECT_FALSE(searchBranchAndBound(pyr, pts, w, 0.1));
    w.centre.head<2>() = at;
    (void)searchBranchAndBound(pyr, pts, w, 0.1);
    EXPECT_EQ(scoreAt(g, pts, {1e30, -1e30, 0}), 0);
    // Rays from the vehicle (0, 0) to there: the grid would span 1e31 cells: refused.
    EXPECT_THROW(buildScoreGrid(hits, res, sigma, pad, {Eigen::Vector2d::Zero()}), std::length_error) << at.transpose();
  }
  // Points 10 km apart, as a sensor mounted at x = 1e4 gave (1.16 GB before): 1e10 cells.
  EXPECT_THROW(buildScoreGrid({{0, 0}, {1e4, 1e4}}, res, sigma, pad), std::length_error);
  EXPECT_THROW(buildScoreGrid({{0, 0}, {1e15, 0}, {0, 1e15}}, res, sigma, pad), std::length_error);
  // A smaller budget is the caller's to give; a kernel wider than the budget is refused too.
  EXPECT_THROW(buildScoreGrid({{0, 0}, {3, 3}}, res, sigma, 0, {}, 100), std::length_error);
  EXPECT_THROW(buildScoreGrid({{0, 0}}, 1e-300, sigma), std::length_error);
  EXPECT_NO_THROW(buildScoreGrid({{0, 0}, {3, 3}}, res, sigma, 0, {}, 40 * 40));
  // The search's pyramid shares its budget among its levels: 7 levels of 9000 x 9000 cells
  // (a ray of 1.3 km) is past it, refused before anything is allocated.
  CorrelativeParams p;
  EXPECT_THROW(searchPyramid({{{0, 0}, {900, 900}}}, p), std::length_error);
  // Rays crossing the grid from far away: only the grid's cells are walked (a ray from 1e6 m
  // took 2e7 steps; from 1e30 the steps stopped moving, s + step == s, and never ended).
  ScoreGrid g = buildScoreGrid({{0, 0}, {2, 2}}, res, sigma, 0);
  markFreeSpace(g, {{{-1e30, 0.05}, {1e30, 0.05}}, {{1.0, -1e300}, {1.0, 1e300}}, {{-1e6, 0.05}, {1e6, 0.05}}}, -255);
  const Eigen::Vector2i mid = g.cellOf({0.0, 0.05}), left = g.cellOf({-0.35, 0.05});
  EXPECT_EQ(g.at(left.x(), left.y()), -255);
  EXPECT_GT(g.at(mid.x(), mid.y()), 0);  // a hit's kernel keeps its value
  EXPECT_EQ(cellFloor(1e30), kFarCell);
  EXPECT_EQ(cellFloor(-1e30), -kFarCell);
  EXPECT_EQ(cellFloor(std::numeric_limits<double>::quiet_NaN()), kFarCell);
  EXPECT_EQ(cellFloor(-2.5), -3);
}

TEST(CorrelativeSearch, WindowsBeyondTheirBoundsAreRefusedBeforeAnyAllocation)
{
  SearchWindow w;
  w.theta_step = 1e-9;
  EXPECT_THROW(windowAngles(w), std::invalid_argument);
  w.theta_step = 0;
  EXPECT_THROW(windowAngles(w), std::invalid_argument);
  w.theta_step = mrpt::DEG2RAD(0.1);
  EXPECT_EQ(windowAngles(w).size(), static_cast<size_t>(kMaxWindowAngles));
  EXPECT_THROW(depthForWindow(1e9, 0.1), std::invalid_argument);
  EXPECT_THROW(depthForWindow(1e300, 1e-300), std::invalid_argument);
  EXPECT_EQ(depthForWindow(kMaxWindowCells * 0.1, 0.1), 12);  // 2049 cells across
}
