#include <swslam/common/ini_file.h>

#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

TEST(IniFile, ReadsKeysOfSections)
{
  const auto path = swslam::test::tempDir("ini_ok") + "/a.ini";
  std::ofstream(path) << "# comment\n[plicp]\nmax_iterations = 40\n; other comment\n[map]\n";
  const auto cfg = swslam::common::readIniFile(path);
  EXPECT_EQ(cfg->read_int("plicp", "max_iterations", 0), 40);
}

TEST(IniFile, AnExpressionMrptCannotExpandIsAnInvalidArgumentNamingTheFile)
{
  // MRPT expands $env{...} even in comments and threw std::runtime_error, which no caller
  // of readIniFile expects (found by fuzzing, tests/fuzz/regressions/ini_config).
  const auto path = swslam::test::tempDir("ini_env") + "/env.ini";
  std::ofstream(path) << "# see doc/s$env{.md)\n[plicp]\nmax_iterations = 40\n";
  try
  {
    swslam::common::readIniFile(path);
    FAIL() << "accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("config: '" + path + "'"), std::string::npos) << e.what();
  }
}

TEST(IniFile, ACountIsDigitsOnlyAndAnythingElseIsNamed)
{
  mrpt::config::CConfigFileMemory cfg("[run]\nscans = 1200\nzero = 0\nnegative = -3\nword = ten\nhalf = 1.5\n"
                                      "huge = 99999999999999999999\n");
  EXPECT_EQ(swslam::common::readIniCount(cfg, "run", "scans", "src"), 1200u);
  EXPECT_EQ(swslam::common::readIniCount(cfg, "run", "zero", "src"), 0u);
  for (const char* key : {"negative", "word", "half", "huge", "missing"})
  {
    try
    {
      swslam::common::readIniCount(cfg, "run", key, "src");
      ADD_FAILURE() << key << " accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind(std::string("src: [run] ") + key + " must be a count, got '", 0), 0u)
          << e.what();
    }
  }
}
