// The scans' self-consistency at a trajectory's poses (swslam-eval consistency).
#include "room_loop.h"
#include "test_support.h"

#include <swslam/eval/consistency.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::eval;
using mrpt::poses::CPose2D;
using test::RoomLoop;

TEST(EvalConsistency, NearbyPairsKeepCloseAndDistantEnoughScans)
{
  const std::vector<CPose2D> poses{{0, 0, 0}, {1, 0, 0}, {2.5, 0, 0}, {0, 0.5, 1}, {10, 0, 0}};
  using Pairs = std::vector<std::pair<size_t, size_t>>;
  EXPECT_EQ(eval::nearbyPairs(poses, 1.6, 1), (Pairs{{0, 1}, {0, 3}, {1, 2}, {1, 3}}));
  EXPECT_EQ(eval::nearbyPairs(poses, 1.6, 2), (Pairs{{0, 3}, {1, 3}}));
  EXPECT_EQ(eval::nearbyPairs(poses, 1.6, 0), eval::nearbyPairs(poses, 1.6, 1));  // never (i, i)
  EXPECT_TRUE(eval::nearbyPairs(poses, 0.1, 1).empty());
}

TEST(EvalConsistency, TruePosesAgreeAndOneWrongPoseShows)
{
  const RoomLoop room;
  eval::ConsistencyOptions o;
  o.radius = 4;
  o.revisit_gap = 8;
  const auto pairs = eval::nearbyPairs(room.poses, o.radius, o.min_gap);
  ASSERT_GT(pairs.size(), 20u);
  const auto truth = eval::scanConsistency(room.scans, room.poses, pairs, o);
  EXPECT_EQ(truth.all.pairs, pairs.size());
  EXPECT_GT(truth.all.points, 100 * pairs.size());
  EXPECT_LT(truth.all.median, 0.01);  // range noise 5 mm
  EXPECT_GT(truth.all.fractionGood(), 0.95);
  EXPECT_LT(truth.all.rms_capped, 0.03);

  // Revisits: exactly the pairs at least revisit_gap scans apart.
  size_t far = 0;
  for (const auto& [i, j] : pairs) far += j - i >= o.revisit_gap;
  ASSERT_GT(far, 0u);
  EXPECT_EQ(truth.revisits.pairs, far);

  // One scan placed 0.25 m and 3 deg off: its pairs disagree.
  auto wrong = room.poses;
  wrong[5] = wrong[5] + CPose2D(0.25, 0, 3 * M_PI / 180);
  const auto bad = eval::scanConsistency(room.scans, wrong, pairs, o);
  EXPECT_LT(bad.all.fractionGood(), truth.all.fractionGood() - 0.05);
  EXPECT_GT(bad.all.rms_capped, truth.all.rms_capped + 0.01);
}

TEST(EvalConsistency, OnlyRelativePosesMatter)
{
  const RoomLoop room;
  eval::ConsistencyOptions o;
  const auto pairs = eval::nearbyPairs(room.poses, o.radius, o.min_gap);
  const CPose2D frame(12, -7, 2.0);  // the whole trajectory in another frame
  std::vector<CPose2D> moved;
  for (const auto& p : room.poses) moved.push_back(frame + p);
  EXPECT_EQ(eval::nearbyPairs(moved, o.radius, o.min_gap), pairs);
  const auto a = eval::scanConsistency(room.scans, room.poses, pairs, o);
  const auto b = eval::scanConsistency(room.scans, moved, pairs, o);
  EXPECT_EQ(a.all.points, b.all.points);
  EXPECT_NEAR(a.all.rms_capped, b.all.rms_capped, 1e-9);
  EXPECT_NEAR(a.all.median, b.all.median, 1e-9);
}

TEST(EvalConsistency, MismatchedInputIsAnError)
{
  const RoomLoop room;
  eval::ConsistencyOptions o;
  auto fewer = room.poses;
  fewer.pop_back();
  EXPECT_THROW(eval::scanConsistency(room.scans, fewer, {{0, 1}}, o), std::invalid_argument);
  EXPECT_THROW(eval::scanConsistency(room.scans, room.poses, {{0, 99}}, o), std::invalid_argument);
  // No pairs: nothing to score, reported as NaN rather than as perfect agreement.
  const auto none = eval::scanConsistency(room.scans, room.poses, {}, o);
  EXPECT_EQ(none.all.points, 0u);
  EXPECT_TRUE(std::isnan(none.all.median));
  EXPECT_TRUE(std::isnan(none.all.fractionGood()));
}

TEST(EvalConsistency, LoadedScansSitAtTheVehiclePoseComposedWithTheMount)
{
  // A sensor mounted 0.4 m ahead and turned 30 deg on a vehicle that turns as it goes: the
  // scans agree only at vehicle pose (+) mount.
  const auto world = test::roomWorld();
  const CPose2D mount(0.4, 0.1, 30 * M_PI / 180);
  std::mt19937 rng(5);
  const std::string dir = test::tempDir("consistency_mount"), log = dir + "/mounted.rawlog";
  std::vector<common::StampedPose> vehicle;
  {
    mrpt::io::CFileGZOutputStream f(log);
    auto arch = mrpt::serialization::archiveFrom(f);
    for (int k = 0; k < 12; k++)
    {
      const CPose2D v(-2 + 0.3 * k, 0.2 * k, 0.15 * k);
      auto obs = test::simulateObservation(world, v + mount, 361, M_PI, 30, 0.005, rng);
      obs.sensorPose = mrpt::poses::CPose3D(mount);
      obs.timestamp = mrpt::Clock::fromDouble(10 + 0.1 * k);
      arch << obs;
      vehicle.push_back({10 + 0.1 * k, v});
    }
  }
  const auto posed = eval::loadPosedScans(log, {vehicle}, 0.01, 1, 0.0, io::CarmenParams());
  ASSERT_EQ(posed.scans.size(), 12u);
  EXPECT_EQ(posed.unposed, 0u);
  for (size_t k = 0; k < 12; k++)
    EXPECT_NEAR((posed.sensor_poses[0][k] - (vehicle[k].pose + mount)).norm(), 0, 1e-6);
  eval::ConsistencyOptions o;
  const auto pairs = eval::nearbyPairs(posed.sensor_poses[0], o.radius, o.min_gap);
  ASSERT_FALSE(pairs.empty());
  const auto mounted = eval::scanConsistency(posed.scans, posed.sensor_poses[0], pairs, o);
  std::vector<CPose2D> bare;
  for (const auto& v : vehicle) bare.push_back(v.pose);
  const auto unmounted = eval::scanConsistency(posed.scans, bare, pairs, o);
  EXPECT_GT(mounted.all.fractionGood(), 0.95);
  EXPECT_LT(unmounted.all.fractionGood(), mounted.all.fractionGood() - 0.2);

  // Every 5th scan: 3 of 12; a stride leaving fewer than 2 scans is an error naming it.
  EXPECT_EQ(eval::loadPosedScans(log, {vehicle}, 0.01, 5, 0.0, io::CarmenParams()).scans.size(), 3u);
  EXPECT_THROW(eval::loadPosedScans(log, {vehicle}, 0.01, 12, 0.0, io::CarmenParams()), std::runtime_error);
}
