// swslam-carmen2rawlog's run: both outputs written and named; an existing one is kept unless
// told to overwrite it.
#include <swslam/app/carmen2rawlog_run.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_support.h"

using namespace swslam::app;

TEST(Carmen2RawlogRun, WritesBothOutputsThenRefusesToOverwriteThemUnlessTold)
{
  const std::string dir = swslam::test::tempDir("carmen2rawlog_run");
  Carmen2RawlogRunOptions o;
  o.input = dir + "/in.log";
  o.output = dir + "/out.rawlog";
  o.ground_truth = dir + "/out.tum";
  std::ofstream(o.input) << "FLASER 5 1.5 2 3 2 1.5 0 0 0 0 0 0 10.00 host 10.00\n"
                            "FLASER 5 1.5 2 3 2 1.5 0.1 0 0 0.1 0 0 10.10 host 10.10\n";
  std::ostringstream out, err;
  ASSERT_EQ(runCarmen2Rawlog(o, out, err), 0) << err.str();
  EXPECT_EQ(out.str().rfind("wrote " + o.output + " and " + o.ground_truth + "\n", 0), 0u) << out.str();
  EXPECT_TRUE(std::filesystem::exists(o.output));

  std::ostringstream out2, err2;
  EXPECT_EQ(runCarmen2Rawlog(o, out2, err2), 1);
  EXPECT_EQ(err2.str(), "swslam-carmen2rawlog: '" + o.output + "' exists (use -w to overwrite)\n");
  o.overwrite = true;
  std::ostringstream out3, err3;
  EXPECT_EQ(runCarmen2Rawlog(o, out3, err3), 0) << err3.str();
}
