// The whole configuration file (app/config.h): every shipped file loads strictly, and wrong keys and
// sections are errors naming them.
#include <swslam/common/param_table.h>
#include <swslam/app/config.h>

#include <swslam/io/hokuyo_link.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/string_utils.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

using namespace swslam;
using namespace swslam::app;

TEST(Config, EveryFileInConfigDirLoads)
{
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SWSLAM_SOURCE_DIR) + "/config"))
  {
    if (e.path().extension() != ".ini") continue;
    files++;
    const mrpt::config::CConfigFile cfg(e.path().string());
    if (cfg.sectionExists("LASER_2D"))  // a sensor config for swslam-live
    {
      EXPECT_NO_THROW(io::checkHokuyoSection(cfg, "LASER_2D")) << e.path();
      EXPECT_NO_THROW(loadConfig(cfg, {"LASER_2D"})) << e.path();
    }
    else
      EXPECT_NO_THROW(loadConfig(e.path().string())) << e.path();
  }
  EXPECT_GE(files, 1u);
}

namespace
{
std::string fileText(const std::string& path)
{
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(Config, TheShippedFilesAreTheTablesOfEveryModule)
{
  // config/default.ini and config/expert.ini are written from the modules' key tables
  // (swslam-config): every key once, with its unit, its doc line and its in-class default.
  const std::string dir = std::string(SWSLAM_SOURCE_DIR) + "/config/";
  EXPECT_EQ(fileText(dir + "default.ini"), shippedConfigFile(common::Tier::User))
      << "write it again: build/apps/swslam-config > config/default.ini";
  EXPECT_EQ(fileText(dir + "expert.ini"), shippedConfigFile(common::Tier::Expert))
      << "write it again: build/apps/swslam-config --tier expert > config/expert.ini";
  // Read back, the two files give the in-class defaults, and each key is in one of them.
  const Config d;
  for (const auto* file : {"default.ini", "expert.ini"})
  {
    const Config loaded = loadConfig(dir + file);
    for (const auto tier : {common::Tier::User, common::Tier::Expert})
      EXPECT_EQ(configText(loaded, tier), configText(d, tier)) << file;
  }
  size_t keys = 0;
  Config::forEachSection(d, [&](const auto& table, const auto&) {
    const auto user = table.names(common::Tier::User), expert = table.names(common::Tier::Expert);
    EXPECT_EQ(user.size() + expert.size(), table.names().size()) << table.section();
    keys += table.names().size();
  });
  EXPECT_GT(keys, 100u);
}

TEST(Config, MisspelledKeyIsAnErrorNamingIt)
{
  mrpt::config::CConfigFileMemory cfg("[plicp]\nmax_iteration = 10\n");
  try
  {
    loadConfig(cfg);
    FAIL();
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("'max_iteration'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[plicp]"), std::string::npos) << e.what();
  }
}

TEST(Config, UnknownSectionIsAnError)
{
  mrpt::config::CConfigFileMemory cfg("[plicpp]\nmax_iterations = 10\n");
  EXPECT_THROW(loadConfig(cfg), std::invalid_argument);
}

TEST(Config, OutOfRangeValueIsAnError)
{
  mrpt::config::CConfigFileMemory cfg("[plicp]\ntrim_keep_fraction = 1.5\n");
  EXPECT_THROW(loadConfig(cfg), std::invalid_argument);
}

namespace
{
/** Loading `text` fails with an error whose message contains `expected`. */
void expectLoadError(const std::string& text, const std::string& expected)
{
  mrpt::config::CConfigFileMemory cfg(text);
  try
  {
    loadConfig(cfg);
    ADD_FAILURE() << "accepted: " << text;
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(Config, AMapTooLargeToAllocateIsAnErrorNotACrash)
{
  // An infinite or huge first map would be cast to a cell count past an int's range.
  expectLoadError("[map]\ninitial_half_size = inf\n", "initial_half_size must be > 0 m");
  for (const char* text : {"[map]\ninitial_half_size = 1e9\n", "[map]\ngrow_margin = 1e9\n",
                           "[map]\nresolution = 0.005\ninitial_half_size = 41\n"})
    expectLoadError(text, "at most 8192 cells");
  mrpt::config::CConfigFileMemory ok("[map]\nresolution = 0.005\ninitial_half_size = 40\n");
  EXPECT_NO_THROW(loadConfig(ok));
}

TEST(Config, ValuesThatWouldStallOrOverflowAreErrorsNamingTheKey)
{
  // Found by a sanitizer campaign: each passed the loader, then made a cast undefined (a huge
  // kernel, an infinite cell or angle step, or a run stall (PLICP
  // running to a huge iteration cap on every scan).
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[correlative]\nsigma = 1e12\n", "sigma"},
      {"[correlative]\nsigma = 10\n", "sigma"},
      {"[correlative]\nresolution = inf\n", "resolution"},
      {"[correlative]\ntheta_step_DEG = inf\n", "theta_step_DEG"},
      {"[correlative]\nwindow_theta_DEG = 1e300\n", "window_theta_DEG"},
      {"[plicp]\nmax_iterations = 1000000\n", "max_iterations"},
      {"[carmen]\nmax_range = 1e300\n", "max_range"}};
  for (const auto& [text, key] : cases)
    expectLoadError(text, key);
}

TEST(Config, AnIntegerKeyReadAsAnotherNumberIsAnError)
{
  // MRPT's reader takes the leading digits of an integer key ("1e3" as 1, "2.5" as 2) and an
  // unsigned "-1" as 2^64 - 1, silently.
  for (const char* text : {"[plicp]\nmax_iterations = 1e3\n", "[plicp]\nmax_iterations = 40.5\n"})
    expectLoadError(text, "is not an integer");
  // A negative count is out of its range before it could wrap.
  expectLoadError("[graph_optimizer]\nfull_optimization_interval = -1\n", "full_optimization_interval = '-1' must be >= 1");
  expectLoadError("[carmen]\nsaturation_min_count = -1\n", "saturation_min_count = '-1' must be >= 1");
  // The same numbers written as integers, and floating-point keys, are taken.
  mrpt::config::CConfigFileMemory ok("[plicp]\nmax_iterations = 1000\nepsilon_xy = 1e-3\n"
                                     "[graph_optimizer]\nfull_optimization_interval = 3\n");
  EXPECT_NO_THROW(loadConfig(ok));
}

TEST(Config, MissingFileIsAnError)
{
  EXPECT_THROW(loadConfig(std::string("/nonexistent/x.ini")), std::invalid_argument);
}

TEST(Config, InlineCommentIsAnErrorNotASilentFalse)
{
  mrpt::config::CConfigFileMemory cfg("[plicp]\nremove_doubles = true   # keep one\n");
  EXPECT_THROW(loadConfig(cfg), std::invalid_argument);
}

TEST(Config, AValueNotOfItsKeysKindIsAnErrorNotASilentZero)
{
  // MRPT reads numbers with atoi/atof and booleans with atoi: each of these loaded silently.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"plicp", "trim_keep_fraction = abc"},  // a number read as 0
      {"plicp", "min_segment_length = 0.3 0.4"},  // read as 0.3
      {"plicp", "max_iterations = 12abc"},      // read as 12
      {"plicp", "remove_doubles = 0x10"},        // a boolean read as false
      {"plicp", "remove_doubles = maybe"},
      {"plicp", "epsilon_xy = nan"},
      {"plicp", "epsilon_xy ="},                 // no value
  };
  for (const auto& [section, line] : bad)
  {
    mrpt::config::CConfigFileMemory cfg("[" + section + "]\n" + line + "\n");
    try
    {
      loadConfig(cfg);
      ADD_FAILURE() << line << " was accepted";
    }
    catch (const std::invalid_argument& e)
    {
      const std::string key = line.substr(0, line.find(' '));
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  // Every spelling MRPT reads as meant still loads, and -inf is a valid kernel shape.
  mrpt::config::CConfigFileMemory good(
      "[plicp]\nmax_iterations = 12\nremove_doubles = no\nepsilon_xy = 1e-4\n"
      "[graph_optimizer]\nkernel_alpha = -inf\n");
  const system::SystemParams p = loadConfig(good).system;
  EXPECT_EQ(p.plicp.max_iterations, 12);
  EXPECT_FALSE(p.plicp.remove_doubles);
  EXPECT_TRUE(std::isinf(p.graph_optimizer.kernel_alpha));
}

TEST(Config, AStrayLineOrARepeatedKeyIsAnErrorNamingTheLine)
{
  // MRPT's reader skipped a line without '=' and kept one of two settings of a key, silently.
  const std::string dir = std::filesystem::temp_directory_path() / "swslam_config_lines";
  std::filesystem::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"[plicp]\nmax_iterations = 12\n# note\nmax_correspondence_dist 2\n", "line 4: 'max_correspondence_dist 2'"},
      {"[plicp]\n= 5\n", "line 2"},
      {"[plicp]\nmax_iterations = 12\n\nMax_Iterations = 40\n", "line 4: key 'Max_Iterations' of [plicp] is set again (first on line 2)"},
  };
  for (const auto& [text, expected] : bad)
  {
    std::ofstream(dir + "/bad.ini") << text;
    try
    {
      loadConfig(dir + "/bad.ini");
      ADD_FAILURE() << text << " was accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  // The same key in two sections is two keys.
  std::ofstream(dir + "/ok.ini") << "[plicp]\nmax_iterations = 12\n[graph_optimizer]\nmax_iterations = 50\n";
  EXPECT_EQ(loadConfig(dir + "/ok.ini").system.plicp.max_iterations, 12);
  std::filesystem::remove_all(dir);
}
