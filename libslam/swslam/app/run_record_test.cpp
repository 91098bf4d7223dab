// run.ini: what a run writes is read back as it was (every config key, the run's options),
// is itself a configuration swslam accepts, and a damaged record is an error naming it.
#include <swslam/app/config.h>
#include <swslam/app/run_record.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace swslam;
using namespace swslam::app;

namespace
{
RunRecord sampleRecord()
{
  RunRecord r;
  r.program = "swslam";
  r.input = "/data/a lake/run 1.rawlog";
  r.use_odometry = false;
  r.deterministic = true;
  r.scan_topic = "/scan";
  r.max_scans = 1200;
  r.throttle_scans = 3;
  r.config.system.map.resolution = 0.15;
  r.config.system.tracking.dense_radius = 2.5;
  r.config.system.graph_optimizer.window_size = 17;
  r.config.carmen.laser_only = true;
  return r;
}

std::string writeFile(const std::string& name, const std::string& text)
{
  const std::string path = (std::filesystem::temp_directory_path() / ("run_record_test_" + name)).string();
  std::ofstream(path) << text;
  return path;
}

std::string savedText(const Config& c)
{
  mrpt::config::CConfigFileMemory m;
  Config::forEachSection(c, [&](const auto& table, const auto& p) { table.save(p, m); });
  std::string s;
  m.getContent(s);
  return s;
}
}  // namespace

TEST(RunRecord, ReadsBackWhatWasWritten)
{
  const RunRecord r = sampleRecord();
  const std::string path = writeFile("roundtrip.ini", runRecordText(r));
  const RunRecord back = readRunRecord(path);
  EXPECT_EQ(back.program, "swslam");
  EXPECT_EQ(back.version, RunRecord::swslamVersion());
  EXPECT_FALSE(back.version.empty());
  EXPECT_EQ(back.input, r.input);
  EXPECT_FALSE(back.use_odometry);
  EXPECT_TRUE(back.deterministic);
  EXPECT_EQ(back.sensor_label, "");
  EXPECT_EQ(back.scan_topic, "/scan");
  EXPECT_EQ(back.max_scans, 1200u);
  EXPECT_EQ(back.throttle_scans, 3u);
  // Every key of every section, as written.
  EXPECT_EQ(savedText(back.config), savedText(r.config));
  EXPECT_EQ(back.config.system.graph_optimizer.window_size, 17u);
  EXPECT_NE(savedText(back.config), savedText(Config()));
  // And the file is a configuration as any other.
  EXPECT_EQ(savedText(loadConfig(path)), savedText(r.config));
}

TEST(RunRecord, ADamagedRecordIsAnErrorNamingIt)
{
  const std::string good = runRecordText(sampleRecord());
  auto expectError = [](const std::string& path, const std::string& words) {
    try
    {
      readRunRecord(path);
      ADD_FAILURE() << "no error for " << path;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expectError("/nonexistent/run.ini", "/nonexistent/run.ini");
  expectError(writeFile("norun.ini", "[map]\nresolution = 0.1\n"), "no [run] section");
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  expectError(writeFile("noinput.ini", replaced("input = /data/a lake/run 1.rawlog", "")), "[run] input is missing");
  expectError(writeFile("badflag.ini", replaced("odometry = false", "odometry = maybe")), "odometry must be true or false");
  expectError(writeFile("badcount.ini", replaced("max_scans = 1200", "max_scans = -3")), "max_scans must be a count");
  expectError(writeFile("badkey.ini", replaced("[map]\n", "[map]\nresolutio = 0.1\n")), "resolutio");
}
