// swslam-rawlog2bag's run: an existing output is kept unless told to overwrite it.
#include <swslam/app/rawlog2bag_run.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_support.h"

using namespace swslam::app;

TEST(Rawlog2BagRun, AnExistingOutputIsRefusedWithoutOverwrite)
{
  const std::string dir = swslam::test::tempDir("rawlog2bag_run");
  Rawlog2BagRunOptions o;
  o.conversion.input = std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog";
  o.conversion.output = dir + "/out.bag";
  std::ofstream(o.conversion.output) << "mine";
  std::ostringstream out, err;
  EXPECT_EQ(runRawlog2Bag(o, out, err), 1);
  EXPECT_EQ(err.str(), "swslam-rawlog2bag: '" + o.conversion.output + "' exists (use -w to overwrite)\n");
  std::ifstream kept(o.conversion.output);
  std::string text;
  kept >> text;
  EXPECT_EQ(text, "mine");
}
