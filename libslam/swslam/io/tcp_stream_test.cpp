// TcpStream against the SCIP emulator sending random bytes from its first one (a peer that
// never stops sending): reads limited in time and stopped on request return at once, and
// the bytes read are counted; a peer that closes makes the stream dead.
#include <swslam/io/tcp_stream.h>

#include "scip/scip_emulator.h"

#include <gtest/gtest.h>

#include <atomic>

namespace swslam::io
{
namespace
{
using namespace std::chrono;

scip::Scan flatScan(uint64_t)
{
  return scip::Scan{std::vector<uint32_t>(scip::SensorInfo{}.steps(), 1000), {}};
}

/** An emulator that sends garbage to every connection from its start. */
scip::EmulatorOptions garbageFromTheStart()
{
  scip::EmulatorOptions o;
  o.faults.garbage_after_scans = 0;
  o.faults.garbage_connections = 1000;
  return o;
}

/** Reads until a read returns nothing; returns the bytes read. */
size_t readAll(TcpStream& s)
{
  char buf[128];
  size_t total = 0;
  while (const size_t n = s.Read(buf, sizeof buf)) total += n;
  return total;
}

TEST(TcpStream, ReadsFromTheLimitOnReturnNothingWhileDataKeepsComing)
{
  scip::ScipEmulator emu(flatScan, garbageFromTheStart());
  TcpStream s("127.0.0.1", emu.port(), milliseconds(1000), milliseconds(100));
  const auto t0 = steady_clock::now();
  s.limitReads(t0 + milliseconds(300));
  const size_t n = readAll(s);
  const auto took = steady_clock::now() - t0;
  EXPECT_GE(took, milliseconds(300));
  EXPECT_LT(took, milliseconds(450));
  EXPECT_TRUE(s.cut());
  EXPECT_FALSE(s.dead());
  EXPECT_GT(n, 5 * scip::kGarbagePerPeriod);  // ~12 periods of garbage
  EXPECT_EQ(s.bytesRead(), n);
  // A new limit: reads go on.
  s.limitReads(steady_clock::now() + milliseconds(100));
  EXPECT_FALSE(s.cut());
  EXPECT_GT(readAll(s), 0u);
  EXPECT_TRUE(s.cut());
}

TEST(TcpStream, AStopCutsReadsAtOnce)
{
  scip::ScipEmulator emu(flatScan, garbageFromTheStart());
  TcpStream s("127.0.0.1", emu.port(), milliseconds(1000), milliseconds(100));
  std::atomic<bool> stop{false};
  s.setStop([&] { return stop.load(); });
  char buf[64];
  const auto t0 = steady_clock::now();
  while (s.Read(buf, sizeof buf) == 0 && steady_clock::now() - t0 < seconds(2))
  {
  }
  ASSERT_GT(s.bytesRead(), 0u);
  stop = true;
  EXPECT_EQ(s.Read(buf, sizeof buf), 0u);
  EXPECT_TRUE(s.cut());
  EXPECT_FALSE(s.dead());
}

TEST(TcpStream, APeerThatClosesMakesTheStreamDead)
{
  auto emu = std::make_unique<scip::ScipEmulator>(flatScan);
  TcpStream s("127.0.0.1", emu->port(), milliseconds(1000), milliseconds(100));
  emu.reset();
  char buf[64];
  const auto t0 = steady_clock::now();
  while (!s.dead() && steady_clock::now() - t0 < seconds(2)) s.Read(buf, sizeof buf);
  EXPECT_TRUE(s.dead());
  EXPECT_FALSE(s.why().empty());
  EXPECT_EQ(s.Write("QT\n", 3), 3u);  // dropped, reported as written
}

TEST(TcpStream, NoListenerIsAnErrorNamingTheAddress)
{
  const uint16_t port = scip::ScipEmulator(flatScan).port();  // closed again
  try
  {
    TcpStream s("127.0.0.1", port, milliseconds(1000), milliseconds(100));
    FAIL() << "connected to a closed port";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("127.0.0.1:" + std::to_string(port)), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swslam::io
