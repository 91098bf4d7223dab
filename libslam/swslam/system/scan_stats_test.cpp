// stats.csv and Table I: every column of a row in the header's order, and Table I's rows for
// the scans the matches could not decide.
#include <swslam/system/scan_stats.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

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
