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
