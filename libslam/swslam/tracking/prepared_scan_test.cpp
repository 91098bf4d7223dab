// A scan's derived forms (prepared_scan.h): each equal to its direct computation, built once.
#include <swslam/tracking/prepared_scan.h>

#include <swslam/correlative/score_grid.h>

#include <gtest/gtest.h>

#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::tracking;

TEST(PreparedScan, EachFormIsItsDirectComputationBuiltOnce)
{
  std::mt19937 rng(3);
  const sensor::Scan scan = sensor::scanFromObservation(
      test::simulateObservation(test::clutteredWorld(5), mrpt::poses::CPose2D(1, -2, 0.4), 361, M_PI, 30, 0.02, rng));
  plicp::PlicpParams plicp;
  plicp.min_segment_length = 0.3;
  const PreparedScan prepared(scan, ScanForms{plicp, 0.2, 12});

  EXPECT_EQ(prepared.scan().points, scan.points);
  EXPECT_EQ(prepared.rotationLength(), sensor::rotationLength(scan.points));
  // The search's points: thinned at the given spacing and range.
  EXPECT_EQ(prepared.searchPoints(), correlative::thinPoints(scan.points, 0.2, 12));
  EXPECT_LT(prepared.searchPoints().size(), scan.points.size());
  // The facing normals and the reference tables, with the given min_segment_length.
  const FacingNormals facing = facingNormals(scan.points, 0.3);
  EXPECT_EQ(prepared.facing()->lo, facing.lo);
  EXPECT_EQ(prepared.facing()->hi, facing.hi);
  EXPECT_EQ(prepared.reference()->scan.points, scan.points);
  EXPECT_EQ(prepared.reference()->index.min_segment, 0.3);
  // Built once: every later step reads the same object.
  EXPECT_EQ(prepared.reference().get(), prepared.reference().get());
  EXPECT_EQ(prepared.facing().get(), prepared.facing().get());
  EXPECT_EQ(&prepared.searchPoints(), &prepared.searchPoints());
}
