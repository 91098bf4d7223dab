// The emulated sensor's command side: replies, MD/ME requests and their scan frames.
#include "scip/scip_encoding.h"
#include "scip/scip_protocol.h"

#include <gtest/gtest.h>

namespace swslam::scip
{
namespace
{
Scan rampScan(const SensorInfo& info)
{
  Scan s;
  for (uint32_t i = 0; i < info.steps(); i++)
  {
    s.ranges_mm.push_back(1000 + 3 * i);
    s.intensities.push_back(i % 4096);
  }
  return s;
}

std::vector<uint32_t> rangesOf(const Frame& f, int chars_per_step)
{
  std::string data;
  for (size_t i = 1; i < f.lines.size(); i++) data += f.lines[i];
  return decodeValues(data, chars_per_step);
}

TEST(ScipProtocol, AnswersTheStartupCommands)
{
  Protocol p;
  EXPECT_EQ(p.reply("SCIP2.0")->status, "0E");
  EXPECT_EQ(p.reply("QT")->status, "00");
  EXPECT_EQ(p.reply("BM")->status, "00");
  EXPECT_TRUE(p.laserOn());
  EXPECT_EQ(p.reply("BM")->status, "02");  // already on
  EXPECT_EQ(p.reply("HS0")->status, "02");  // already off
  EXPECT_EQ(p.reply("HS1")->status, "00");
  EXPECT_EQ(p.reply("HS2")->status, "01");
  EXPECT_EQ(p.reply("CR05")->status, "00");
  EXPECT_EQ(p.reply("CR55")->status, "01");
  EXPECT_EQ(p.reply("XX")->status, "0E");
  EXPECT_FALSE(p.reply(""));
  EXPECT_EQ(p.reply("QT\r")->echo, "QT");
  EXPECT_EQ(p.reply("QT;tag1")->echo, "QT;tag1");
  EXPECT_FALSE(p.laserOn());
}

TEST(ScipProtocol, ReportsTheUtm30lxParameters)
{
  Protocol p;
  const auto pp = p.reply("PP");
  ASSERT_TRUE(pp);
  EXPECT_TRUE(pp->info_lines);
  const std::vector<std::string> expected{"MODL:UTM-30LX", "DMIN:23",  "DMAX:60000",
                                          "ARES:1440",     "AMIN:0",   "AMAX:1080",
                                          "AFRT:540",      "SCAN:2400"};
  EXPECT_EQ(pp->lines, expected);
  const auto vv = p.reply("VV");
  ASSERT_TRUE(vv);
  EXPECT_EQ(vv->lines.at(3), "PROT:SCIP 2.0");
}

TEST(ScipProtocol, RejectsMalformedRequests)
{
  Protocol p;
  EXPECT_EQ(p.reply("MD00001080010")->status, "0C");   // too short
  EXPECT_EQ(p.reply("MD0x00108001000")->status, "01");  // start
  EXPECT_EQ(p.reply("MD00001y8001000")->status, "02"); // end
  EXPECT_EQ(p.reply("MD00001080z1000")->status, "03"); // cluster
  EXPECT_EQ(p.reply("MD000010810100")->status, "0C");
  EXPECT_EQ(p.reply("MD0000108101000")->status, "04"); // beyond AMAX
  EXPECT_EQ(p.reply("MD0500010001000")->status, "05"); // end before start
  EXPECT_EQ(p.reply("MD0000108001s00")->status, "06"); // scan interval
  EXPECT_EQ(p.reply("MD00001080010q0")->status, "07"); // number of scans
  EXPECT_FALSE(p.measurement());
}

TEST(ScipProtocol, EndlessRequestStreamsEveryStep)
{
  Protocol p;
  EXPECT_EQ(p.reply("MD0000108001000")->status, "00");
  ASSERT_TRUE(p.measurement());
  EXPECT_TRUE(p.laserOn());
  const Scan scan = rampScan(p.info());
  for (int i = 0; i < 3; i++)
  {
    ASSERT_TRUE(p.scanDue());
    const Frame f = p.scanFrame(scan, 25 * i);
    EXPECT_EQ(f.echo, "MD0000108001000");
    EXPECT_EQ(f.status, "99");
    EXPECT_EQ(decode(f.lines.at(0)), 25u * i);
    EXPECT_EQ(f.lines.size(), 1u + 51u);
    EXPECT_EQ(rangesOf(f, 3), scan.ranges_mm);
  }
  EXPECT_EQ(p.reply("QT")->status, "00");
  EXPECT_FALSE(p.measurement());
  EXPECT_FALSE(p.scanDue());
}

TEST(ScipProtocol, FiniteRequestCountsDownInItsEcho)
{
  Protocol p;
  p.reply("MD0044072501003");
  const Scan scan = rampScan(p.info());
  std::vector<std::string> echoes;
  while (p.measurement()) echoes.push_back(p.scanFrame(scan, 0).echo);
  EXPECT_EQ(echoes, (std::vector<std::string>{"MD0044072501002", "MD0044072501001",
                                              "MD0044072501000"}));
}

TEST(ScipProtocol, ClusterScanIntervalAndIntensity)
{
  Protocol p;
  SensorInfo info;
  const Scan scan = rampScan(info);
  // Steps 10..19 in clusters of 3: 10-12, 13-15, 16-18, 19; each reports its smallest range.
  p.reply("ME0010001903200");
  ASSERT_TRUE(p.measurement()->intensity);
  const std::vector<uint32_t> values = rangesOf(p.scanFrame(scan, 0), 3);
  EXPECT_EQ(values, (std::vector<uint32_t>{1030, 10, 1039, 13, 1048, 16, 1057, 19}));
  // Scan interval 2: one period in three.
  std::string due;
  for (int i = 0; i < 7; i++) due += p.scanDue() ? '1' : '0';
  EXPECT_EQ(due, "1001001");
}

TEST(ScipProtocol, ScanOfTheWrongSizeIsAnError)
{
  Protocol p;
  p.reply("MD0000108001000");
  Scan scan = rampScan(p.info());
  scan.ranges_mm.pop_back();
  EXPECT_THROW(p.scanFrame(scan, 0), std::invalid_argument);
  Scan big = rampScan(p.info());
  big.ranges_mm[5] = 1u << 18;  // does not fit in 3 characters
  EXPECT_THROW(p.scanFrame(big, 0), std::invalid_argument);
  EXPECT_THROW(Protocol(SensorInfo{"X", 23, 60000, 1440, 10, 5, 7, 2400, "S"}),
               std::invalid_argument);
}

}  // namespace
}  // namespace swslam::scip
