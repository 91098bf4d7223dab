// stats.csv and Table I: every column of a row in the header's order, read back as written
// (an older file's header too, a bad value named by line and column), and Table I's rows for
// the scans the matches could not decide.
#include <swslam/common/atomic_file.h>
#include <swslam/system/scan_stats.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

using namespace swslam;

namespace
{
std::vector<std::string> splitCsv(const std::string& line)
{
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}
}  // namespace

TEST(ScanStats, EachRowHasTheHeadersColumnsInItsOrder)
{
  system::ScanStats r;
  r.scan = 7;
  r.timestamp = 1700000000.25;
  r.source = tracking::TrackingSource::Searched;
  r.valid_rays = 361;
  r.correspondences = 300;
  r.keyframe = 3;
  r.new_node = true;
  r.loops = 2;
  r.switched_off = 4;
  r.ambiguous = 2;
  r.prior_decided = 1;
  std::istringstream csv(system::formatStatsCsv({r}));
  std::string header, row, rest;
  ASSERT_TRUE(std::getline(csv, header));
  ASSERT_TRUE(std::getline(csv, row));
  EXPECT_FALSE(std::getline(csv, rest)) << "one row per scan";
  const auto names = splitCsv(header), values = splitCsv(row);
  ASSERT_EQ(names.size(), values.size());
  auto value = [&](const std::string& name) {
    for (size_t k = 0; k < names.size(); k++)
      if (names[k] == name) return values[k];
    ADD_FAILURE() << "no column " << name;
    return std::string();
  };
  EXPECT_EQ(value("scan"), "7");
  EXPECT_EQ(value("timestamp"), "1700000000.250000");
  EXPECT_EQ(value("source"), "searched");
  EXPECT_EQ(value("valid_rays"), "361");
  EXPECT_EQ(value("correspondences"), "300");
  EXPECT_EQ(value("keyframe"), "3");
  EXPECT_EQ(value("new_node"), "1");
  EXPECT_EQ(value("loops"), "2");
  EXPECT_EQ(value("switched_off"), "4");
  EXPECT_EQ(value("ambiguous"), "2");
  EXPECT_EQ(value("prior_decided"), "1");
  EXPECT_EQ(names.back(), "prior_decided") << "new columns go last (scripts/plot-stats.py reads older files)";
}

TEST(ScanStats, TableIGivesTheAmbiguousScansAndThoseThePredictionDecided)
{
  system::RunSummary s;
  s.scans = 100;
  s.ambiguous_scans = 40;
  s.prior_decided_scans = 3;
  const std::string t = system::formatRunSummary(s);
  EXPECT_NE(t.find("| Ambiguous scans (weak direction or second peak) | 40 |"), std::string::npos) << t;
  EXPECT_NE(t.find("| of them decided by the prediction along a direction | 3 |"), std::string::npos) << t;
}

TEST(ScanStats, ReadStatsCsvReadsBackWhatFormatStatsCsvWrote)
{
  std::vector<system::ScanStats> rows(3);
  for (size_t k = 0; k < rows.size(); k++)
  {
    rows[k].scan = 10 + k;
    rows[k].timestamp = 1700000000.5 + k;
    rows[k].valid_rays = 181;
    rows[k].match_ms = 0.25 * k;
    rows[k].keyframe = k;
  }
  rows[1].source = tracking::TrackingSource::ConstantMotion;
  rows[2].source = tracking::TrackingSource::Match;
  rows[2].ambiguous = 2;
  rows[2].prior_decided = 1;
  rows[2].new_node = true;
  const std::string dir = test::tempDir("scan_stats");
  common::writeTextAtomically(dir + "/stats.csv", system::formatStatsCsv(rows));
  const auto back = system::readStatsCsv(dir + "/stats.csv");
  ASSERT_EQ(back.size(), rows.size());
  for (size_t k = 0; k < rows.size(); k++)
  {
    EXPECT_EQ(back[k].scan, rows[k].scan);
    EXPECT_NEAR(back[k].timestamp, rows[k].timestamp, 1e-6);
    EXPECT_EQ(back[k].source, rows[k].source);
    EXPECT_EQ(back[k].valid_rays, rows[k].valid_rays);
    EXPECT_DOUBLE_EQ(back[k].match_ms, rows[k].match_ms);
    EXPECT_EQ(back[k].keyframe, rows[k].keyframe);
    EXPECT_EQ(back[k].new_node, rows[k].new_node);
    EXPECT_EQ(back[k].ambiguous, rows[k].ambiguous);
    EXPECT_EQ(back[k].prior_decided, rows[k].prior_decided);
    EXPECT_EQ(back[k].placedByPrediction(), rows[k].placedByPrediction());
  }
  EXPECT_TRUE(back[1].placedByPrediction());
  EXPECT_TRUE(back[2].placedByPrediction());
  EXPECT_FALSE(back[0].placedByPrediction());

  // Values of over 300 characters each are written whole (a line buffer would cut them).
  rows[0].timestamp = 1e300;
  rows[0].match_ms = 1e300;
  common::writeTextAtomically(dir + "/huge.csv", system::formatStatsCsv(rows));
  const auto huge = system::readStatsCsv(dir + "/huge.csv");
  ASSERT_EQ(huge.size(), rows.size());
  EXPECT_DOUBLE_EQ(huge[0].timestamp, 1e300);
  EXPECT_DOUBLE_EQ(huge[0].match_ms, 1e300);
  EXPECT_EQ(huge[0].prior_decided, rows[0].prior_decided);
}

TEST(ScanStats, ReadStatsCsvTakesAnOlderHeaderAndNamesTheLineAndColumnOfABadValue)
{
  const std::string dir = test::tempDir("scan_stats_bad");
  const std::string older =
      "scan,timestamp,source,valid_rays,correspondences,match_sq_residuals,active_sq_residuals,match_ms,"
      "tracking_ms,graph_ms,map_ms,keyframe,new_node,loops,full_optimization,switched_off,ambiguous\n";
  const std::string good_row = "0,1700000000.000000,first,436,0,0,0,0.0000,0.1625,0.0223,0.2431,0,1,0,0,0,1\n";
  common::writeTextAtomically(dir + "/older.csv", older + good_row);
  const auto rows = system::readStatsCsv(dir + "/older.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].ambiguous, 1);
  EXPECT_EQ(rows[0].prior_decided, 0);

  auto error = [&](const std::string& text) {
    common::writeTextAtomically(dir + "/bad.csv", text);
    try
    {
      system::readStatsCsv(dir + "/bad.csv");
    }
    catch (const std::runtime_error& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error(older + "0,1700000000,guess,436,0,0,0,0,0,0,0,0,1,0,0,0,1\n").find("line 2: column 'source': 'guess'"),
            std::string::npos);
  EXPECT_NE(error(older + good_row + "1,nan,match,436,0,0,0,0,0,0,0,0,1,0,0,0,1\n").find("line 3: column 'timestamp'"),
            std::string::npos);
  EXPECT_NE(error(older + "0,1700000000,match,-4,0,0,0,0,0,0,0,0,1,0,0,0,1\n").find("column 'valid_rays'"),
            std::string::npos);
  EXPECT_NE(error(older + "0,1700000000,match,4,0,0,0,0,0,0,0,0,1,0,0,0,99\n").find("column 'ambiguous'"),
            std::string::npos);
  EXPECT_NE(error(older + "0,1700000000,match,4,0\n").find("line 2: 5 values, expected 17"), std::string::npos);
  EXPECT_NE(error(older + "0,1700000000,match,4,0,0,0,0,0,0,0,0,1,0,0,0,\n").find("column 'ambiguous': ''"),
            std::string::npos);
  EXPECT_NE(error("scan,time\n").find("line 1: not the header"), std::string::npos);
  EXPECT_NE(error("").find("line 1: empty file"), std::string::npos);
  EXPECT_THROW(system::readStatsCsv(dir + "/missing.csv"), std::runtime_error);
}
