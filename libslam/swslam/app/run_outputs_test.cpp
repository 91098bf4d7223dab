// A run's Table I and files: the distance travelled follows the keyframes, not the scan-to-scan
// jitter; ambiguous scans are counted apart from fallbacks; writeRunOutputs writes exactly
// the files runOutputFiles() names.
#include <swslam/app/run_outputs.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "test_support.h"

using namespace swslam;
using mrpt::poses::CPose2D;

namespace
{
/** 10 m along x in 1001 scans that jitter 2 cm sideways, a keyframe every metre. */
system::RunResults straightRunWithJitter()
{
  system::RunResults r;
  for (int k = 0; k <= 1000; k++)
  {
    r.trajectory.push_back({0.01 * k, CPose2D(0.01 * k, k % 2 ? 0.02 : 0.0, 0)});
    r.stats.push_back(system::ScanStats{});
    r.stats.back().scan = k;
  }
  for (int m = 0; m <= 9; m++)
  {
    r.keyframes.push_back({1.0 * m, CPose2D(m, 0, 0)});
    r.graph.addNode(m, CPose2D(m, 0, 0));
  }
  return r;
}
}  // namespace

TEST(RunOutputs, TheDistanceFollowsTheKeyframesNotTheJitter)
{
  const system::RunSummary s = app::summarizeRun(straightRunWithJitter(), 1.0);
  EXPECT_NEAR(s.distance, 10.0, 1e-9);  // 9 m of keyframes, then 1 m to the last scan
  EXPECT_EQ(s.scans, 1001u);
  EXPECT_EQ(s.nodes, 10u);
}

TEST(RunOutputs, ScansThePredictionPlacedAreCountedAndMarkedForThePictures)
{
  system::RunResults r = straightRunWithJitter();
  auto set = [&](size_t k, tracking::TrackingSource source, int ambiguous, int prior_decided) {
    r.stats[k].source = source;
    r.stats[k].ambiguous = ambiguous;
    r.stats[k].prior_decided = prior_decided;
  };
  set(10, tracking::TrackingSource::Match, 1, 0);     // a weak direction, reported only
  set(11, tracking::TrackingSource::Match, 2, 1);     // the prediction decided one of two
  set(12, tracking::TrackingSource::Searched, 1, 1);  // ... the only one
  set(13, tracking::TrackingSource::ConstantMotion, 0, 0);
  set(14, tracking::TrackingSource::Odometry, 1, 1);  // a fallback counts as such only
  const system::RunSummary s = app::summarizeRun(r, 1.0);
  EXPECT_EQ(s.fallback_scans, 2u);
  EXPECT_EQ(s.ambiguous_scans, 3u);
  EXPECT_EQ(s.prior_decided_scans, 2u);
  // The pictures mark the scans the prediction placed: by fallback, or along a direction.
  const map::Overlay o = app::overlayOf(r);
  ASSERT_EQ(o.by_prediction.size(), o.trajectory.size());
  EXPECT_EQ(o.countByPrediction(), 4u);
  for (const size_t k : {11, 12, 13, 14}) EXPECT_TRUE(o.by_prediction[k]) << k;
  EXPECT_FALSE(o.by_prediction[10]) << "a weak direction only reported";
}

TEST(RunOutputs, EveryFileWrittenIsNamedByRunOutputFiles)
{
  const std::string dir = test::tempDir("run_outputs");
  const system::RunResults r = straightRunWithJitter();
  mrpt::maps::COccupancyGridMap2D grid(-5, 15, -5, 5, 0.1);
  auto problems = app::writeRunOutputs(dir, r, grid, map::MapParams(), "# summary\n", "[run]\n", false);
  // A resumed run's change report too.
  map::ChangeReport changes;
  changes.resolution = 0.1;
  app::writeChangeOutputs(dir, grid, map::Overlay(), changes, problems);
  EXPECT_TRUE(problems.empty());
  std::set<std::string> written, named;
  for (const auto& e : std::filesystem::directory_iterator(dir)) written.insert(e.path().filename().string());
  for (const auto& f : app::runOutputFiles())
    if (f != "render.png") named.insert(f);
  EXPECT_EQ(written, named);
}

TEST(RunOutputs, TheLastLineNamesOnlyTheOutputsThatExist)
{
  // After a full disk it still listed stats.csv and summary.md, which were not written.
  const std::string dir = test::tempDir("run_outputs_line");
  for (const char* name : {"map.png", "trajectory.tum", "map.yaml"}) std::ofstream(dir + "/" + name) << "x";
  EXPECT_EQ(app::outputsLine(dir, false), "# outputs in " + dir +
                                         "/ (map.png, trajectory.tum); not written: map.gridmap.gz, map.pgm, map.bt, "
                                         "keyframes.tum, graph.graph, stats.csv, summary.md, run.ini\n");
  for (const auto& name : app::runOutputFiles()) std::ofstream(dir + "/" + name) << "x";
  EXPECT_EQ(app::outputsLine(dir, true),
            "# outputs in " + dir + "/ (map.png, render.png, trajectory.tum, stats.csv, summary.md)\n");
}
