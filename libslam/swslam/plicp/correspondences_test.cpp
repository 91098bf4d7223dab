// The fast correspondence search equals the brute-force one (as csm checks in debug).
#include <swslam/plicp/correspondences.h>
#include <swslam/plicp/outliers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::plicp;

namespace
{
void expectSameAsBruteForce(const sensor::Scan& ref, const sensor::Scan& cur, const mrpt::poses::CPose2D& q,
                            double max_dist, double min_segment)
{
  std::vector<Eigen::Vector2d> pts;
  for (const auto& p : cur.points)
  {
    double gx, gy;
    q.composePoint(p.x(), p.y(), gx, gy);
    pts.emplace_back(gx, gy);
  }
  const ReferenceIndex index(ref, min_segment);
  const auto fast = findCorrespondences(ref, index, pts, max_dist);
  const auto slow = findCorrespondencesBruteForce(ref, pts, max_dist, min_segment);
  ASSERT_EQ(fast.size(), slow.size());
  for (size_t k = 0; k < fast.size(); k++)
  {
    ASSERT_EQ(fast[k], slow[k]) << "point " << slow[k].i << ": fast j1 " << fast[k].j1
                                << " slow j1 " << slow[k].j1;
    ASSERT_DOUBLE_EQ(fast[k].dist2, slow[k].dist2);
  }
}

/** A scan of `world` from a random pose, and one after a random motion from there: `beams`
 * rays over `fov_deg` (a 360° scan does not repeat its first ray), 3 cm range noise. */
struct ScanPair
{
  sensor::Scan ref, cur;
  mrpt::poses::CPose2D motion;
};
ScanPair randomScanPair(const test::World& world, double fov_deg, size_t beams, std::mt19937& rng)
{
  std::uniform_real_distribution<double> U(-1, 1);
  const double fov = fov_deg * M_PI / 180 * (fov_deg == 360 ? (beams - 1.0) / beams : 1.0);
  const mrpt::poses::CPose2D ref_pose(2 * U(rng), -2 + U(rng), U(rng));
  const mrpt::poses::CPose2D motion(0.5 * U(rng), 0.5 * U(rng), 0.3 * U(rng));
  auto ref = sensor::scanFromObservation(test::simulateObservation(world, ref_pose, beams, fov, 30, 0.03, rng));
  auto cur = sensor::scanFromObservation(
      test::simulateObservation(world, ref_pose + motion, beams, fov, 30, 0.03, rng));
  return {std::move(ref), std::move(cur), motion};
}
}  // namespace

TEST(PlicpCorrespondences, FastSearchEqualsBruteForce)
{
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> U(-1, 1);
  const auto world = test::clutteredWorld(1);
  for (double fov_deg : {180.0, 270.0, 360.0})
  {
    const size_t beams = fov_deg == 180 ? 181 : (fov_deg == 270 ? 1081 : 720);
    for (int trial = 0; trial < 6; trial++)
    {
      const auto [ref, cur, motion] = randomScanPair(world, fov_deg, beams, rng);
      // From the truth, from a perturbed guess, and from identity; several thresholds.
      for (double max_dist : {0.3, 1.5, 1e9})
      {
        const double seg = trial % 2 ? 0.0 : 0.2;
        expectSameAsBruteForce(ref, cur, motion, max_dist, seg);
        expectSameAsBruteForce(ref, cur, mrpt::poses::CPose2D(), max_dist, seg);
        expectSameAsBruteForce(ref, cur, mrpt::poses::CPose2D(U(rng), U(rng), 2 * U(rng)), max_dist, seg);
      }
    }
  }
}

TEST(PlicpCorrespondences, JumpTablesPointAtTheNextLongerAndShorterRay)
{
  sensor::Scan s;
  s.ranges = {3, 1, 2, 5, 4, 4, 1};
  s.beam_count = s.ranges.size();
  s.aperture = M_PI;
  for (size_t i = 0; i < s.ranges.size(); i++)
  {
    s.angles.push_back(-M_PI / 2 + M_PI * i / 6);
    s.points.emplace_back(s.ranges[i] * std::cos(s.angles[i]), s.ranges[i] * std::sin(s.angles[i]));
  }
  const ReferenceIndex idx(s, 0.0);
  const int n = 7;
  for (int i = 0; i < n; i++)
  {
    int ub = i + 1, us = i + 1, db = i - 1, ds = i - 1;
    while (ub < n && s.ranges[ub] <= s.ranges[i]) ub++;
    while (us < n && s.ranges[us] >= s.ranges[i]) us++;
    while (db >= 0 && s.ranges[db] <= s.ranges[i]) db--;
    while (ds >= 0 && s.ranges[ds] >= s.ranges[i]) ds--;
    EXPECT_EQ(idx.up_bigger[i], ub) << i;
    EXPECT_EQ(idx.up_smaller[i], us) << i;
    EXPECT_EQ(idx.down_bigger[i], db) << i;
    EXPECT_EQ(idx.down_smaller[i], ds) << i;
  }
}

TEST(PlicpOutliers, KeepsOnlyTheNearestMatchPerReferencePoint)
{
  std::vector<Correspondence> out = {{0, 5, 6, 0.3}, {1, 5, 4, 0.1}, {2, 7, 8, 0.2}, {3, 5, 6, 0.2}};
  keepNearestPerReference(out, 10);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].i, 1);
  EXPECT_EQ(out[1].i, 2);
}

TEST(PlicpOutliers, TrimsTheWorstFractionAndAdaptiveOutliers)
{
  std::vector<Correspondence> in;
  std::vector<double> err;
  for (int k = 0; k < 100; k++)
  {
    in.push_back({k, k, k + 1, 0});
    err.push_back(k < 95 ? 0.01 * (1 + k % 5) : 10.0);  // 5 gross outliers
  }
  auto kept = in;
  auto kept_err = err;
  trimByError(kept, kept_err, 0.99, 0.7, 3.0);
  EXPECT_EQ(kept.size(), 95u);
  ASSERT_EQ(kept_err.size(), kept.size());
  for (size_t k = 0; k < kept.size(); k++)
  {
    EXPECT_LT(kept[k].i, 95);
    EXPECT_EQ(kept_err[k], err[kept[k].i]);  // errors stay aligned with their correspondences
  }
  // Median of the 100 errors is 0.03; 19 of each of 0.01..0.05: 57 are <= 0.03.
  kept = in;
  kept_err = err;
  trimByError(kept, kept_err, 0.5, 1.0, 100);
  EXPECT_EQ(kept.size(), 57u);
}

TEST(PlicpCorrespondences, PseudoAngleIsMonotoneInTheAngle)
{
  double previous = -3;
  for (int k = 0; k < 3600; k++)
  {
    const double a = -M_PI + 2 * M_PI * k / 3600;
    const double pa = pseudoAngle(std::cos(a), std::sin(a));
    EXPECT_GT(pa, previous) << "angle " << a;
    EXPECT_GE(pa, -2.0);
    EXPECT_LT(pa, 2.0);
    previous = pa;
  }
  EXPECT_NEAR(pseudoAngle(1, 0), 0, 1e-15);
  EXPECT_NEAR(pseudoAngle(0, 1), 1, 1e-15);
  EXPECT_NEAR(pseudoAngle(0, -1), -1, 1e-15);
}

TEST(PlicpCorrespondences, CloseSurfacesOfDenseScansStillDefineALine)
{
  // 361 beams over 180 deg, everything 0.3 m away: 8 rays span 2 cm, short of a 0.2 m
  // segment. The segment then ends at the 8th ray (the scan's end, walking off it), so that
  // a robot close to a wall keeps its correspondences there.
  mrpt::obs::CObservation2DRangeScan obs;
  obs.aperture = static_cast<float>(M_PI);
  obs.maxRange = 20;
  obs.resizeScan(361);
  for (size_t i = 0; i < 361; i++)
  {
    obs.setScanRange(i, 0.3f);
    obs.setScanRangeValidity(i, true);
  }
  const sensor::Scan s = sensor::scanFromObservation(obs);
  EXPECT_EQ(segmentEnd(s, false, 100, +1, 0.2), 108);
  EXPECT_EQ(segmentEnd(s, false, 100, -1, 0.2), 92);
  EXPECT_EQ(segmentEnd(s, false, 357, +1, 0.2), 360);
  EXPECT_EQ(segmentEnd(s, false, 360, +1, 0.2), -1);
  EXPECT_EQ(segmentEnd(s, false, 100, +1, 0.0), 101);  // Censi's neighbour
  const ReferenceIndex index(s, 0.2);
  std::vector<Eigen::Vector2d> pts(s.points.begin(), s.points.end());
  for (auto& p : pts) p *= 1.01;  // 3 mm behind the surface
  const auto found = findCorrespondences(s, index, pts, 0.5);
  EXPECT_EQ(found.size(), s.size());
  for (const auto& c : found) EXPECT_NE(c.j2, -1);
}

TEST(PlicpCorrespondences, SearchMemoryEqualsBruteForceAlongAnIcpLikeSequence)
{
  // A sequence of poses that converges like ICP (steps shrinking from centimetres to
  // micrometres), with a few jumps and radius changes: every step's result equals the brute
  // force, and most points of the small steps are answered from the memory.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  const auto world = test::clutteredWorld(1);
  size_t reused = 0, searched = 0;
  for (double fov_deg : {180.0, 270.0, 360.0})
  {
    const size_t beams = fov_deg == 180 ? 361 : (fov_deg == 270 ? 1081 : 720);
    for (int trial = 0; trial < 3; trial++)
    {
      const auto [ref, cur, motion] = randomScanPair(world, fov_deg, beams, rng);
      const double seg = trial % 2 ? 0.0 : 0.2;
      const ReferenceIndex index(ref, seg);
      SearchMemory memory;
      Eigen::Vector3d x(motion.x() + 0.05 * U(rng), motion.y() + 0.05 * U(rng),
                        motion.phi() + 0.02 * U(rng));
      for (int step = 0; step < 14; step++)
      {
        const double scale = step == 7 ? 0.3 : 0.03 * std::pow(0.3, step % 7);  // a jump at 7
        x += scale * Eigen::Vector3d(U(rng), U(rng), 0.3 * U(rng));
        const double max_dist = step < 3 ? 2.0 : (step == 10 ? 1e9 : 0.5);
        std::vector<Eigen::Vector2d> pts;
        const double c = std::cos(x.z()), s = std::sin(x.z());
        for (const auto& p : cur.points)
          pts.emplace_back(c * p.x() - s * p.y() + x.x(), s * p.x() + c * p.y() + x.y());
        const auto fast = findCorrespondences(ref, index, pts, max_dist, memory);
        const auto slow = findCorrespondencesBruteForce(ref, pts, max_dist, seg);
        ASSERT_EQ(fast.size(), slow.size()) << "step " << step;
        for (size_t k = 0; k < fast.size(); k++)
        {
          ASSERT_EQ(fast[k], slow[k]) << "step " << step << " point " << slow[k].i;
          ASSERT_DOUBLE_EQ(fast[k].dist2, slow[k].dist2);
        }
      }
      reused += memory.reused;
      searched += memory.searched;
    }
  }
  EXPECT_GT(reused, searched);  // the memory does answer most small steps
}
