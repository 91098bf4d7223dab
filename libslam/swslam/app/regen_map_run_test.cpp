// swslam-regen-map's run: a resolution out of [map]'s range is named as the option, before
// anything is read or written.
#include <swslam/app/regen_map_run.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "test_support.h"

using namespace swslam::app;

TEST(RegenMapRun, AResolutionOutOfRangeIsNamedAsTheOption)
{
  const std::string dir = swslam::test::tempDir("regen_map_run");
  RegenMapOptions o;
  o.run = dir + "/no-run";
  o.input = dir + "/no-log.rawlog";
  o.output = dir + "/map";
  o.config = std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini";
  o.resolution = 1e9;
  std::ostringstream out, err;
  EXPECT_EQ(runRegenMap(o, out, err), 1);
  EXPECT_EQ(err.str().rfind("swslam-regen-map: --resolution 1000000000.000000: ", 0), 0u) << err.str();
  EXPECT_EQ(out.str(), "");
  EXPECT_FALSE(std::filesystem::exists(o.output));
}
