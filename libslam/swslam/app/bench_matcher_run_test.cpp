// swslam-bench-matcher's run: a stride of 0 is refused before the log is read.
#include <swslam/app/bench_matcher_run.h>

#include <gtest/gtest.h>

#include <sstream>

#include "test_support.h"

using namespace swslam::app;

TEST(BenchMatcherRun, AStrideOfZeroIsRefused)
{
  BenchMatcherOptions o;
  o.input = "no-such.rawlog";
  o.ground_truth = "no-such.tum";
  o.stride = 0;
  std::ostringstream out, err;
  EXPECT_EQ(runBenchMatcher(o, out, err), 1);
  EXPECT_EQ(err.str(), "swslam-bench-matcher: --stride must be >= 1\n");
}
