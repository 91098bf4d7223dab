// A run's Table I and files: the distance travelled follows the keyframes, not the scan-to-scan
// jitter; writeRunOutputs writes exactly the files runOutputFiles() names.
#include <swslam/app/run_outputs.h>

#include <gtest/gtest.h>

#include <filesystem>
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

TEST(RunOutputs, EveryFileWrittenIsNamedByRunOutputFiles)
{
  const std::string dir = test::tempDir("run_outputs");
  const system::RunResults r = straightRunWithJitter();
  mrpt::maps::COccupancyGridMap2D grid(-5, 15, -5, 5, 0.1);
  const auto problems = app::writeRunOutputs(dir, r, grid, map::MapParams(), "# summary\n", false);
  EXPECT_TRUE(problems.empty());
  std::set<std::string> written, named;
  for (const auto& e : std::filesystem::directory_iterator(dir)) written.insert(e.path().filename().string());
  for (const auto& f : app::runOutputFiles())
    if (f != "render.png") named.insert(f);
  EXPECT_EQ(written, named);
}
