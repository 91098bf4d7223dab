// The SCIP emulator over loopback TCP, seen by a raw client: replies, streaming at the
// scan rate with correct encoding, checksums and timestamps, faults, drops, reconnection.
#include "scip/scip_emulator.h"
#include "scip/scip_encoding.h"
#include "scip/scip_test_client.h"

#include <gtest/gtest.h>

namespace swslam::scip
{
namespace
{
using std::chrono::milliseconds;
constexpr milliseconds kWait(2000);

/** A scene that changes with k and along the scan. */
Scan rampScan(uint64_t k)
{
  Scan s;
  for (uint32_t i = 0; i < SensorInfo{}.steps(); i++)
    s.ranges_mm.push_back(i % 97 == 0 ? kNoEcho : static_cast<uint32_t>(500 + 11 * i + 3 * k));
  return s;
}

std::vector<uint32_t> rangesOf(const ParsedFrame& f)
{
  std::string data;
  for (size_t i = 1; i < f.frame.lines.size(); i++) data += f.frame.lines[i];
  return decodeValues(data, 3);
}

TEST(ScipEmulator, PortZeroPicksAFreePort)
{
  ScipEmulator a(rampScan), b(rampScan);
  EXPECT_NE(a.port(), 0);
  EXPECT_NE(b.port(), 0);
  EXPECT_NE(a.port(), b.port());
  EmulatorOptions taken;
  taken.port = a.port();
  EXPECT_THROW(ScipEmulator(rampScan, taken), std::runtime_error);
}

TEST(ScipEmulator, StreamsEncodedScansWithTimestamps)
{
  EmulatorOptions opt;
  opt.first_timestamp_ms = kTimestampModulo - 60;  // wraps after the third scan
  ScipEmulator emu(rampScan, opt);
  TestClient client(emu.port());
  client.send("PP");
  const auto pp = client.readFrame(kWait);
  ASSERT_TRUE(pp);
  EXPECT_TRUE(pp->checksums_ok);
  EXPECT_EQ(pp->frame.lines.at(2), "DMAX:60000");

  client.send("MD0000108001000");
  const auto ack = client.readFrame(kWait);
  ASSERT_TRUE(ack);
  EXPECT_EQ(ack->frame.status, "00");
  EXPECT_TRUE(ack->frame.lines.empty());
  std::vector<ParsedFrame> scans;
  for (int i = 0; i < 6; i++)
  {
    auto f = client.readFrame(kWait);
    ASSERT_TRUE(f);
    scans.push_back(*f);
  }
  const auto sent = emu.sentScans();
  ASSERT_GE(sent.size(), scans.size());
  for (size_t i = 0; i < scans.size(); i++)
  {
    const ParsedFrame& f = scans[i];
    EXPECT_EQ(f.frame.echo, "MD0000108001000");
    EXPECT_EQ(f.frame.status, "99");
    EXPECT_TRUE(f.checksums_ok);
    const uint32_t stamp = decode(f.frame.lines.at(0));
    EXPECT_EQ(stamp, sent[i].timestamp_ms);
    EXPECT_EQ(stamp, (opt.first_timestamp_ms + 25 * sent[i].k) % kTimestampModulo);
    EXPECT_EQ(rangesOf(f), rampScan(sent[i].k).ranges_mm);
    EXPECT_EQ(sent[i].number, i);
    EXPECT_EQ(sent[i].connection, 1u);
    if (i > 0)
    {
      EXPECT_EQ(sent[i].k, sent[i - 1].k + 1) << "a scan period was skipped";
    }
  }
  client.send("QT");
  ASSERT_TRUE(client.readFrameEchoing("QT", kWait));
  EXPECT_TRUE(emu.waitFor([](const EmulatorStats& s) { return !s.streaming; }, kWait));
  const auto s = emu.stats();
  EXPECT_EQ(s.commands, (std::vector<std::string>{"PP", "MD0000108001000", "QT"}));
  EXPECT_TRUE(s.error.empty());
}

TEST(ScipEmulator, DropsAfterNScansThenAcceptsTheNextConnection)
{
  EmulatorOptions opt;
  opt.faults.drop_after_scans = 3;
  ScipEmulator emu(rampScan, opt);
  {
    TestClient client(emu.port());
    client.send("MD0000108001000");
    ASSERT_TRUE(client.readFrame(kWait));  // the acknowledgement
    for (int i = 0; i < 3; i++) ASSERT_TRUE(client.readFrame(kWait)) << i;
    EXPECT_TRUE(client.waitClosed(kWait));
    EXPECT_TRUE(client.pending().empty());
  }
  EXPECT_TRUE(emu.waitFor([](const EmulatorStats& s) { return s.drops == 1; }, kWait));
  TestClient again(emu.port());
  again.send("MD0000108001000");
  ASSERT_TRUE(again.readFrame(kWait));
  for (int i = 0; i < 5; i++) ASSERT_TRUE(again.readFrame(kWait)) << "dropped again at " << i;
  const auto s = emu.stats();
  EXPECT_EQ(s.connections, 2u);
  EXPECT_EQ(s.drops, 1u);
  EXPECT_EQ(emu.sentScans().back().connection, 2u);
}

TEST(ScipEmulator, GarbageAfterNScansReplacesScipOnThatConnectionOnly)
{
  EmulatorOptions opt;
  opt.faults.garbage_after_scans = 3;
  ScipEmulator emu(rampScan, opt);
  {
    TestClient client(emu.port());
    client.send("MD0000108001000");
    ASSERT_TRUE(client.readFrame(kWait));  // the acknowledgement
    for (int i = 0; i < 3; i++)
    {
      const auto scan = client.readFrame(kWait);
      ASSERT_TRUE(scan) << i;
      EXPECT_TRUE(scan->checksums_ok);
    }
    ASSERT_TRUE(emu.waitFor([](const EmulatorStats& s) { return s.garbage_bytes >= 4 * kGarbagePerPeriod; },
                            kWait));
    client.send("QT");  // heard, not answered
    EXPECT_FALSE(client.waitClosed(milliseconds(300)));
    EXPECT_GE(client.pending().size(), kGarbagePerPeriod);
    EXPECT_EQ(client.pending().find("QT\n00P\n"), std::string::npos);
  }
  const auto s = emu.stats();
  EXPECT_EQ(s.scans_sent, 3u);
  EXPECT_EQ(s.commands.back(), "QT");
  EXPECT_EQ(s.garbage_bytes % kGarbagePerPeriod, 0u);
  TestClient again(emu.port());  // the next connection speaks SCIP
  again.send("PP");
  const auto pp = again.readFrame(kWait);
  ASSERT_TRUE(pp);
  EXPECT_EQ(pp->frame.echo, "PP");
  EXPECT_TRUE(pp->checksums_ok);
}

TEST(ScipEmulator, GarbageFromTheStartForTheFirstConnections)
{
  EmulatorOptions opt;
  opt.faults.garbage_after_scans = 0;
  opt.faults.garbage_connections = 2;
  ScipEmulator emu(rampScan, opt);
  for (uint64_t n = 1; n <= 2; n++)
  {
    TestClient client(emu.port());
    client.send("PP");
    EXPECT_FALSE(client.waitClosed(milliseconds(300))) << n;
    EXPECT_GE(client.pending().size(), kGarbagePerPeriod) << n;
    EXPECT_EQ(client.pending().find("PP\n00P\n"), std::string::npos) << n;
    ASSERT_TRUE(emu.waitFor([&](const EmulatorStats& s) { return s.connections == n; }, kWait));
  }
  TestClient third(emu.port());
  third.send("PP");
  const auto pp = third.readFrame(kWait);
  ASSERT_TRUE(pp);
  EXPECT_EQ(pp->frame.echo, "PP");
  EXPECT_EQ(emu.stats().scans_sent, 0u);
}

TEST(ScipEmulator, DropMidFrameCutsTheLastScan)
{
  EmulatorOptions opt;
  opt.faults.drop_after_scans = 2;
  opt.faults.drop_mid_frame = true;
  ScipEmulator emu(rampScan, opt);
  TestClient client(emu.port());
  client.send("MD0000108001000");
  ASSERT_TRUE(client.readFrame(kWait));
  ASSERT_TRUE(client.readFrame(kWait));
  EXPECT_FALSE(client.readFrame(kWait));  // half a frame, then the connection closes
  EXPECT_TRUE(client.waitClosed(kWait));
  EXPECT_FALSE(client.pending().empty());
}

TEST(ScipEmulator, DropConnectionOnRequestAndNewConnectionsReplaceOldOnes)
{
  ScipEmulator emu(rampScan);
  TestClient first(emu.port());
  first.send("BM");
  ASSERT_TRUE(first.readFrame(kWait));
  emu.dropConnection();
  EXPECT_TRUE(first.waitClosed(kWait));

  TestClient second(emu.port());
  second.send("BM");
  const auto bm = second.readFrame(kWait);
  ASSERT_TRUE(bm);
  EXPECT_EQ(bm->frame.status, "00");  // a new connection starts with the laser off
  TestClient third(emu.port());
  EXPECT_TRUE(second.waitClosed(kWait));
  third.send("QT");
  EXPECT_TRUE(third.readFrame(kWait));
  const auto s = emu.stats();
  EXPECT_EQ(s.connections, 3u);
  EXPECT_EQ(s.drops, 1u);
  EXPECT_EQ(s.disconnects, 1u);
}

TEST(ScipEmulator, MalformedRepliesAndScansOnTheWire)
{
  EmulatorOptions opt;
  opt.faults.scans = {{1, Fault::BadChecksum}, {2, Fault::TruncatedLine}, {3, Fault::WrongEcho}};
  opt.faults.replies = {{"PP", Fault::BadChecksum}};
  ScipEmulator emu(rampScan, opt);
  TestClient client(emu.port());
  client.send("PP");
  const auto pp = client.readFrame(kWait);
  ASSERT_TRUE(pp);
  EXPECT_FALSE(pp->checksums_ok);
  client.send("MD0000108001000");
  ASSERT_TRUE(client.readFrame(kWait));
  std::vector<ParsedFrame> f;
  for (int i = 0; i < 5; i++)
  {
    auto frame = client.readFrame(kWait);
    ASSERT_TRUE(frame);
    f.push_back(*frame);
  }
  const auto sent = emu.sentScans();
  EXPECT_TRUE(f[0].checksums_ok);
  EXPECT_FALSE(f[1].checksums_ok);
  EXPECT_EQ(rangesOf(f[1]), rampScan(sent[1].k).ranges_mm);  // only the checksum is wrong
  EXPECT_FALSE(f[2].checksums_ok);
  EXPECT_EQ(f[2].frame.lines.at(0).size(), 1u);  // "XXXXs" cut to "XX": 1 character + sum
  EXPECT_EQ(f[3].frame.echo, "MD0000108001001");
  EXPECT_TRUE(f[3].checksums_ok);
  EXPECT_TRUE(f[4].checksums_ok);
  EXPECT_EQ(f[4].frame.echo, "MD0000108001000");
  EXPECT_EQ(sent[1].fault, Fault::BadChecksum);
  EXPECT_EQ(sent[4].fault, Fault::None);
}

TEST(ScipEmulator, SourceFailureIsReportedAndClosesTheConnection)
{
  ScipEmulator emu([](uint64_t) { return Scan{std::vector<uint32_t>(100, 1000), {}}; });
  TestClient client(emu.port());
  client.send("MD0000108001000");
  ASSERT_TRUE(client.readFrame(kWait));
  EXPECT_TRUE(client.waitClosed(kWait));
  EXPECT_TRUE(emu.waitFor([](const EmulatorStats& s) { return !s.error.empty(); }, kWait));
  EXPECT_NE(emu.stats().error.find("100 ranges"), std::string::npos) << emu.stats().error;
}

}  // namespace
}  // namespace swslam::scip
