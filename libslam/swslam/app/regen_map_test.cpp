// Rebuilding a run's map from its graph and the log, at another resolution; the run's
// stats.csv for its pictures only when it has a row per trajectory pose.
#include <swslam/app/regen_map.h>
#include <swslam/common/atomic_file.h>
#include <swslam/io/scan_source.h>
#include <swslam/map/octomap_export.h>
#include <swslam/system/slam_system.h>

#include <gtest/gtest.h>

#include "test_support.h"

using namespace swslam;
using namespace swslam::app;

TEST(RegenMap, RebuildsTheRunsMapAtAFinerResolution)
{
  const std::string log = std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog";
  const system::SystemParams params = system::loadSystemParams(std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini");
  system::SlamSystem slam(params, system::RunMode::Deterministic);
  auto src = io::openScanSource(log, io::ScanSourceOptions{}, io::CarmenParams());
  sensor::ScanInput in;
  for (int i = 0; i < 600 && src->next(in); i++) ASSERT_TRUE(slam.feed(in).ok());
  slam.finish();
  const system::RunResults run = slam.results();
  const auto online = slam.mapSnapshot();

  // Same resolution: every node inserted at its final pose; the online map holds nodes at
  // poses within the re-insertion threshold of those, so the two agree almost everywhere.
  RegenReport report;
  const auto same = regenerateMap(run.graph, run.keyframes, log, params.map, io::CarmenParams(), io::ScanSourceOptions(), &report);
  EXPECT_EQ(report.inserted, run.graph.nodeCount());
  const double occ = map::countOccupied(online, params.map.occupied_thresh);
  EXPECT_NEAR(map::countOccupied(same, params.map.occupied_thresh), occ, 0.1 * occ);

  map::MapParams fine = params.map;
  fine.resolution = 0.1;
  const auto offline = regenerateMap(run.graph, run.keyframes, log, fine, io::CarmenParams(), io::ScanSourceOptions());
  EXPECT_NEAR(offline.getResolution(), 0.1, 1e-6);
  EXPECT_GT(map::countOccupied(offline, fine.occupied_thresh), 1.5 * occ);

  // Keyframes of another run: an error naming the problem.
  auto wrong = run.keyframes;
  wrong.pop_back();
  EXPECT_THROW(regenerateMap(run.graph, wrong, log, params.map, io::CarmenParams(), io::ScanSourceOptions()), std::runtime_error);
  wrong = run.keyframes;
  wrong.back().t += 0.0123;
  try
  {
    regenerateMap(run.graph, wrong, log, params.map, io::CarmenParams(), io::ScanSourceOptions());
    FAIL() << "no error";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("is not in"), std::string::npos) << e.what();
  }
}

TEST(RegenMap, StatsForThePicturesOnlyWithOneRowPerTrajectoryPose)
{
  const std::string dir = test::tempDir("regen_stats");
  std::string problem = "stale";
  EXPECT_TRUE(app::statsForPictures(dir + "/none.csv", 3, problem).empty());
  EXPECT_EQ(problem, "") << "an older run without stats.csv: nothing to say";
  std::vector<system::ScanStats> rows(3);
  rows[1].source = tracking::TrackingSource::Odometry;
  common::writeTextAtomically(dir + "/stats.csv", system::formatStatsCsv(rows));
  const auto back = app::statsForPictures(dir + "/stats.csv", 3, problem);
  EXPECT_EQ(problem, "");
  ASSERT_EQ(back.size(), 3u);
  EXPECT_TRUE(back[1].placedByPrediction());
  EXPECT_TRUE(app::statsForPictures(dir + "/stats.csv", 4, problem).empty());
  EXPECT_NE(problem.find("has 3 rows for a trajectory of 4 poses"), std::string::npos) << problem;
  common::writeTextAtomically(dir + "/stats.csv", "scan,oops\n");
  EXPECT_TRUE(app::statsForPictures(dir + "/stats.csv", 3, problem).empty());
  EXPECT_NE(problem.find("line 1: not the header"), std::string::npos) << problem;
}
