// swslam-bench-map's run: a missing input is named with the program's name and exits 1.
#include <swslam/app/bench_map_run.h>

#include <gtest/gtest.h>

#include <sstream>

#include "test_support.h"

using namespace swslam::app;

TEST(BenchMapRun, AMissingInputIsNamed)
{
  const std::string dir = swslam::test::tempDir("bench_map_run");
  BenchMapOptions o;
  o.input = dir + "/no-such.rawlog";
  o.ground_truth = std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.gt.tum";
  std::ostringstream out, err;
  EXPECT_EQ(runBenchMap(o, out, err), 1);
  EXPECT_EQ(err.str().rfind("swslam-bench-map: ", 0), 0u) << err.str();
  EXPECT_NE(err.str().find("no-such.rawlog"), std::string::npos) << err.str();
}
