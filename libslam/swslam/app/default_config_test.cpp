// With no -c, a program uses the installed default.ini, else the source tree's: a file that loads.
#include <swslam/app/default_config.h>

#include <swslam/system/config.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace swslam;

TEST(DefaultConfig, TheInstalledOneFirstThenTheSourceTreesAndItLoads)
{
  const auto candidates = app::defaultConfigCandidates();
  ASSERT_EQ(candidates.size(), 2u);
  EXPECT_NE(candidates[0].find("/share/swslam/config/default.ini"), std::string::npos) << candidates[0];
  EXPECT_EQ(candidates[1], std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini");
  const std::string path = app::defaultConfigPath();
  EXPECT_TRUE(std::filesystem::is_regular_file(path));
  EXPECT_NO_THROW(system::loadSystemParams(path));
  EXPECT_EQ(app::configOrDefault("x.ini"), "x.ini");
  EXPECT_EQ(app::configOrDefault(""), path);
}
