// SCIP 2.0 frames: serializing and parsing agree, and each fault breaks what it says.
#include "scip/scip_encoding.h"
#include "scip/scip_frame.h"

#include <gtest/gtest.h>

namespace swslam::scip
{
namespace
{
Frame ppFrame()
{
  return Frame{"PP", "00", {"MODL:UTM-30LX-EW", "DMIN:23", "DMAX:60000"}, true};
}

Frame scanFrame()
{
  std::string data;
  for (uint32_t r = 0; r < 30; r++) data += encode(1000 + 7 * r, 3);
  Frame f{"MD0000002901000", "99", {encode(1000, 4)}, false};
  for (auto& b : splitBlocks(data)) f.lines.push_back(b);
  return f;
}

TEST(ScipFrame, SerializesAsTheSensorDoes)
{
  EXPECT_EQ(serialize(Frame{"QT", "00", {}, false}), "QT\n00P\n\n");
  EXPECT_EQ(serialize(ppFrame()), "PP\n00P\nMODL:UTM-30LX-EW;I\nDMIN:23;7\nDMAX:60000;J\n\n");
  const std::string scan = serialize(scanFrame());
  EXPECT_EQ(scan.substr(0, 26), "MD0000002901000\n99b\n00?Xg\n");  // 'g': checksum of "00?X"
}

TEST(ScipFrame, ParsesWhatItSerializes)
{
  for (const Frame& f : {ppFrame(), scanFrame(), Frame{"BM", "02", {}, false}})
  {
    const std::string bytes = serialize(f);
    const auto p = parseFrame(bytes + "QT\n");  // followed by the start of another reply
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->checksums_ok);
    EXPECT_EQ(p->bytes, bytes.size());
    EXPECT_EQ(p->frame.echo, f.echo);
    EXPECT_EQ(p->frame.status, f.status);
    EXPECT_EQ(p->frame.lines, f.lines);
    EXPECT_EQ(p->frame.info_lines, f.info_lines);
  }
}

TEST(ScipFrame, IncompleteFramesAreNotParsed)
{
  const std::string bytes = serialize(scanFrame());
  for (size_t n = 0; n < bytes.size(); n++) ASSERT_FALSE(parseFrame(bytes.substr(0, n))) << n;
}

TEST(ScipFrame, BadChecksumBreaksOnlyTheChecksum)
{
  const std::string good = serialize(ppFrame()), bad = serialize(ppFrame(), Fault::BadChecksum);
  ASSERT_EQ(good.size(), bad.size());
  EXPECT_EQ(bad, "PP\n00P\nMODL:UTM-30LX-EW;J\nDMIN:23;7\nDMAX:60000;J\n\n");
  const auto p = parseFrame(bad);
  ASSERT_TRUE(p);
  EXPECT_FALSE(p->checksums_ok);
  // Without lines after the status, the status line is the one corrupted.
  EXPECT_EQ(serialize(Frame{"QT", "00", {}, false}, Fault::BadChecksum), "QT\n00Q\n\n");
}

TEST(ScipFrame, TruncatedLineLosesItsSecondHalf)
{
  const std::string bytes = serialize(scanFrame(), Fault::TruncatedLine);
  EXPECT_EQ(bytes.substr(0, 23), "MD0000002901000\n99b\n00\n");
  const auto p = parseFrame(bytes);
  ASSERT_TRUE(p);
  EXPECT_FALSE(p->checksums_ok);
  EXPECT_EQ(p->frame.lines.size(), scanFrame().lines.size());
  EXPECT_EQ(serialize(Frame{"BM", "00", {}, false}, Fault::TruncatedLine), "BM\n0\n\n");
}

TEST(ScipFrame, WrongEchoChangesTheEchoOnly)
{
  const auto p = parseFrame(serialize(scanFrame(), Fault::WrongEcho));
  ASSERT_TRUE(p);
  EXPECT_EQ(p->frame.echo, "MD0000002901001");
  EXPECT_TRUE(p->checksums_ok);
  EXPECT_EQ(p->frame.lines, scanFrame().lines);
  EXPECT_EQ(serialize(Frame{"QT", "00", {}, false}, Fault::WrongEcho), "Q0\n00P\n\n");
}

TEST(ScipFrame, FaultNames)
{
  for (Fault f : {Fault::None, Fault::BadChecksum, Fault::TruncatedLine, Fault::WrongEcho})
    EXPECT_EQ(parseFault(faultName(f)), f);
  try
  {
    parseFault("bad-sum");
    FAIL() << "an unknown fault name was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("bad-sum"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("truncated-line"), std::string::npos);
  }
}

}  // namespace
}  // namespace swslam::scip
