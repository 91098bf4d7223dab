// How far the scans' own constraints pull a trajectory (swslam-eval laser-optimum).
#include "room_loop.h"
#include "test_support.h"

#include <swslam/eval/laser_optimum.h>

#include <mrpt/math/wrap2pi.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::eval;
using mrpt::poses::CPose2D;
using test::RoomLoop;

namespace
{
double maxPositionError(const std::vector<CPose2D>& a, const std::vector<CPose2D>& b)
{
  double m = 0;
  for (size_t k = 0; k < a.size(); k++) m = std::max(m, (a[k] - b[k]).norm());
  return m;
}
}  // namespace

TEST(LaserOptimum, TruePosesHardlyMove)
{
  const RoomLoop room;
  const auto r = eval::laserOptimum(room.scans, room.poses, plicp::PlicpParams(), graph::GraphOptimizerParams(),
                                    eval::LaserOptimumOptions());
  EXPECT_EQ(r.report.status, graph::OptimizationStatus::Converged) << r.report.message;
  EXPECT_EQ(r.failed_consecutive, 0u);
  EXPECT_GT(r.edges, 2 * room.scans.size());  // consecutive and dense pairs
  ASSERT_EQ(r.optimum.size(), room.poses.size());
  // 5 mm range noise; the first pose is held, the error grows around the loop.
  EXPECT_LT(maxPositionError(r.optimum, room.poses), 0.03);
}

TEST(LaserOptimum, TheScansPullAWrongPoseBack)
{
  const RoomLoop room;
  auto given = room.poses;
  given[6] = given[6] + CPose2D(0.15, -0.08, 2 * M_PI / 180);  // within the 0.3 m, 5 deg gate
  given[11] = given[11] + CPose2D(-0.1, 0.1, -1.5 * M_PI / 180);
  eval::LaserOptimumOptions o;
  o.dense_max_index_gap = 4;  // pairs further apart are loop edges, under the robust kernel
  const auto r = eval::laserOptimum(room.scans, given, plicp::PlicpParams(), graph::GraphOptimizerParams(), o);
  EXPECT_EQ(r.report.status, graph::OptimizationStatus::Converged) << r.report.message;
  EXPECT_GT(maxPositionError(given, room.poses), 0.15);
  EXPECT_LT(maxPositionError(r.optimum, room.poses), 0.02);
  EXPECT_NEAR(mrpt::math::wrapToPi(r.optimum[6].phi() - room.poses[6].phi()), 0, 0.3 * M_PI / 180);
}

TEST(LaserOptimum, AnUnmatchableScanKeepsItsGivenPoseThroughWeakEdges)
{
  RoomLoop room;
  sensor::Scan& blind = room.scans[5];  // no valid ray: every match with it fails
  blind.angles.clear();
  blind.ranges.clear();
  blind.points.clear();
  blind.beam_index.clear();
  auto given = room.poses;
  given[5] = given[5] + CPose2D(0.2, 0, 0);
  const auto r = eval::laserOptimum(room.scans, given, plicp::PlicpParams(), graph::GraphOptimizerParams(),
                                    eval::LaserOptimumOptions());
  EXPECT_EQ(r.report.status, graph::OptimizationStatus::Converged) << r.report.message;
  EXPECT_EQ(r.failed_consecutive, 2u);  // 4 -> 5 and 5 -> 6
  // Its neighbours' steps tie it: it keeps its place relative to them, and they stay put.
  EXPECT_LT((r.optimum[5] - given[5]).norm(), 0.03);  // not pulled back to the truth, 0.2 m off
  EXPECT_LT(maxPositionError(r.optimum, given), 0.03);
}

TEST(LaserOptimum, MismatchedInputIsAnError)
{
  const RoomLoop room;
  auto fewer = room.poses;
  fewer.pop_back();
  EXPECT_THROW(eval::laserOptimum(room.scans, fewer, plicp::PlicpParams(), graph::GraphOptimizerParams(),
                                  eval::LaserOptimumOptions()),
               std::invalid_argument);
  EXPECT_THROW(eval::laserOptimum({room.scans[0]}, {room.poses[0]}, plicp::PlicpParams(),
                                  graph::GraphOptimizerParams(), eval::LaserOptimumOptions()),
               std::invalid_argument);
}

TEST(LaserOptimum, OptionsComeFromTheRunsTrackingAndLoopSections)
{
  tracking::TrackingParams t;
  t.dense_radius = 2.5;
  t.dense_max_index_gap = 12;
  t.dense_gate_xy = 0.2;
  t.dense_gate_theta = 0.05;
  t.lost_prior_sigma_xy = 2.0;
  t.lost_prior_sigma_theta = 0.3;
  loop::LoopClosureParams l;
  l.min_inlier_fraction = 0.4;
  const auto o = eval::laserOptimumOptions(t, l);
  EXPECT_EQ(o.radius, 2.5);
  EXPECT_EQ(o.dense_max_index_gap, 12u);
  EXPECT_EQ(o.gate_xy, 0.2);
  EXPECT_EQ(o.gate_theta, 0.05);
  EXPECT_EQ(o.failed_sigma_xy, 2.0);
  EXPECT_EQ(o.failed_sigma_theta, 0.3);
  EXPECT_EQ(o.min_inlier_fraction, 0.4);
}
