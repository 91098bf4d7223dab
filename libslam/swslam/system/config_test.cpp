// The system's sections (system/config.h): rules between them, and sections that belong to
// another program.
#include <swslam/system/config.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace swslam::system;

TEST(Config, BrokenCrossSectionRuleIsAnErrorNamingBothKeys)
{
  mrpt::config::CConfigFileMemory cfg(
      "[tracking]\ndense_max_index_gap = 40\n[loop_closure]\nmin_index_gap = 30\n");
  try
  {
    loadSystemParams(cfg);
    FAIL() << "expected std::invalid_argument";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("dense_max_index_gap"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("min_index_gap"), std::string::npos);
  }
}

TEST(Config, OtherProgramsSectionsAreAllowedOnlyWhenNamed)
{
  const mrpt::config::CConfigFileMemory cfg("[plicp]\nrange_sigma = 0.02\n[LASER_2D]\ndriver = CHokuyoURG\n");
  EXPECT_THROW(loadSystemParams(cfg), std::invalid_argument);
  EXPECT_EQ(loadSystemParams(cfg, {"LASER_2D"}).plicp.range_sigma, 0.02);
  // The sections' names, in file order.
  EXPECT_EQ(SystemParams::sections().front(), "plicp");
  EXPECT_EQ(SystemParams::sections().back(), "system");
}
