// swslam-sim's run: a problem is named with the program's name and exits 1.
#include <swslam/app/sim_run.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "test_support.h"

using namespace swslam::app;

TEST(SimRun, AMissingScenarioIsNamedAndNothingIsWritten)
{
  const std::string dir = swslam::test::tempDir("sim_run");
  SimOptions o;
  o.scenario = dir + "/no-such.ini";
  o.output = dir + "/out";
  std::ostringstream out, err;
  EXPECT_EQ(runSim(o, out, err), 1);
  EXPECT_EQ(out.str(), "");
  EXPECT_EQ(err.str().rfind("swslam-sim: ", 0), 0u) << err.str();
  EXPECT_NE(err.str().find("no-such.ini"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(o.output));
}
