// Decimation of the current scan in PLICP's iterations, then a full-resolution step.
#include <swslam/plicp/decimation.h>
#include <swslam/plicp/plicp.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::plicp;

TEST(PlicpDecimation, StrideFollowsTheBeamSpacing)
{
  sensor::Scan s;
  s.beam_count = 1081;
  s.aperture = 1.5 * M_PI;  // 0.25 deg between beams
  EXPECT_EQ(plicp::decimationStride(s, 1.0 * M_PI / 180), 4u);
  EXPECT_EQ(plicp::decimationStride(s, 0.5 * M_PI / 180), 2u);
  EXPECT_EQ(plicp::decimationStride(s, 0.0), 1u);
  s.beam_count = 181;
  s.aperture = M_PI;  // 1 deg
  EXPECT_EQ(plicp::decimationStride(s, 1.0 * M_PI / 180), 1u);
  s.beam_count = 1;  // degenerate geometry: no decimation
  EXPECT_EQ(plicp::decimationStride(s, 1.0 * M_PI / 180), 1u);
}

TEST(PlicpDecimation, KeepsEveryKthValidRayWithItsSensor)
{
  std::mt19937 rng(3);
  const sensor::Scan s = sensor::scanFromObservation(
      test::simulateObservation(test::roomWorld(), {0, 0, 0}, 361, M_PI, 30, 0.0, rng));
  const sensor::Scan d = plicp::decimated(s, 3);
  ASSERT_EQ(d.size(), (s.size() + 2) / 3);
  for (size_t k = 0; k < d.size(); k++)
  {
    EXPECT_EQ(d.beam_index[k], s.beam_index[3 * k]);
    EXPECT_EQ(d.ranges[k], s.ranges[3 * k]);
    EXPECT_EQ(d.points[k], s.points[3 * k]);
  }
  EXPECT_EQ(d.beam_count, s.beam_count);
  EXPECT_EQ(d.sensor_label, s.sensor_label);
  EXPECT_EQ(plicp::decimated(s, 1).size(), s.size());
}

TEST(PlicpDecimation, MatchEndsWithEveryRay)
{
  std::mt19937 rng(5);
  const auto world = test::clutteredWorld(3);
  const mrpt::poses::CPose2D at(0, -3, 0.1), motion(0.35, 0.05, 0.08);
  const ReferenceScan ref(
      sensor::scanFromObservation(test::simulateObservation(world, at, 1081, 1.5 * M_PI, 30, 0.03, rng)));
  const sensor::Scan cur = sensor::scanFromObservation(
      test::simulateObservation(world, at + motion, 1081, 1.5 * M_PI, 30, 0.03, rng));
  PlicpParams p;
  p.point_spacing = 1.0 * M_PI / 180;  // every 4th ray
  const MatchResult r = matchScans(ref, cur, motion, p);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.pose.x(), motion.x(), 0.03);
  EXPECT_NEAR(r.pose.y(), motion.y(), 0.03);
  EXPECT_NEAR(r.pose.phi(), motion.phi(), 0.3 * M_PI / 180);
  // The final correspondence set (and the covariance) come from all rays, not a quarter.
  EXPECT_GT(r.correspondences, cur.size() / 2);
}
