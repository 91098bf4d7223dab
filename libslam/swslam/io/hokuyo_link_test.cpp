// MRPT's Hokuyo driver (mrpt::hwdrivers::CHokuyoURG, Ethernet mode) against the SCIP
// emulator over loopback TCP: the commands it sends, the scans it returns (equal to the
// emulator's), and how it reports a dropped connection, an unreachable sensor and
// malformed replies. What these tests pin down about MRPT 2.5's driver:
// - initialize() runs the start-up sequence twice (QT QT SCIP2.0 BM HS0 PP VV MD...);
// - it reconnects by itself after the sensor closes the connection, logging an error;
// - with the sensor unreachable, doProcessSimple() returns at once setting hardwareError
//   or throws, reconnects once the sensor is back, and a write to the closed socket raises
//   SIGPIPE;
// - it ignores checksums, silently skips a scan whose echo is wrong, and reports a scan
//   with a truncated line (hardwareError and an error log);
// - the aperture it reports is 1081 steps x 0.25 deg = 270.25 deg, not 270 deg.
#include <swslam/io/hokuyo_link.h>

#include <mrpt/config/CConfigFileMemory.h>

#include "scip/scip_emulator.h"
#include "scip/scip_sim_source.h"
#include "sim_test_scenario.h"

#include <mrpt/hwdrivers/CHokuyoURG.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <memory>

namespace swslam::scip
{
namespace
{
using std::chrono::milliseconds;
using Observation = mrpt::obs::CObservation2DRangeScan;

/** The small test world, seen by a UTM-30LX-like sensor (1081 rays over 270 deg, 40 Hz). */
SimScanSource utmSource()
{
  sim::Scenario sc = test::smallScenario();
  sc.sensor.resolution = 0.25 * M_PI / 180;
  sc.sensor.rate = 40;
  return SimScanSource(sc);
}

/** The driver with its error log captured; every call bounded. */
class Driver
{
 public:
  explicit Driver(uint16_t port)
  {
    // MRPT writes to its socket without MSG_NOSIGNAL: a write to a connection the sensor
    // closed raises SIGPIPE, which kills the process unless ignored (a live app must too).
    std::signal(SIGPIPE, SIG_IGN);
    laser_.setIPandPort("127.0.0.1", port);
    laser_.logging_enable_console_output = false;
    laser_.logRegisterCallback([this](std::string_view msg, mrpt::system::VerbosityLevel level,
                                      std::string_view, mrpt::Clock::time_point) {
      if (level >= mrpt::system::LVL_ERROR) errors.emplace_back(msg);
    });
  }
  void initialize() { static_cast<mrpt::hwdrivers::CGenericSensor&>(laser_).initialize(); }

  /** Polls until `n` observations arrived or `timeout` passed. */
  std::vector<Observation> collect(size_t n, milliseconds timeout)
  {
    std::vector<Observation> got;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (got.size() < n && std::chrono::steady_clock::now() < deadline)
    {
      bool is_obs = false, hw_error = false;
      Observation obs;
      try
      {
        laser_.doProcessSimple(is_obs, obs, hw_error);
      }
      catch (const std::exception& e)
      {
        exceptions.emplace_back(e.what());
        continue;
      }
      hardware_errors += hw_error;
      if (is_obs) got.push_back(obs);
    }
    return got;
  }

  std::vector<std::string> errors, exceptions;
  size_t hardware_errors = 0;

 private:
  mrpt::hwdrivers::CHokuyoURG laser_;
};

/** The sent scan whose ranges the observation holds (exactly, as MRPT converts mm to m). */
const SentScan* matchSent(const Observation& obs, const std::vector<SentScan>& sent)
{
  for (const auto& s : sent)
  {
    if (s.scan.ranges_mm.size() != obs.getScanSize()) continue;
    bool same = true;
    for (size_t i = 0; same && i < obs.getScanSize(); i++)
      same = obs.getScanRange(i) == s.scan.ranges_mm[i] * 0.001f;
    if (same) return &s;
  }
  return nullptr;
}

bool contains(const std::vector<std::string>& lines, const std::string& what)
{
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(what) != std::string::npos; });
}

TEST(HokuyoDriver, InitializesAndStreamsTheEmulatorsScans)
{
  ScipEmulator emu(utmSource());
  Driver driver(emu.port());
  driver.initialize();
  const auto commands = emu.stats().commands;
  const std::vector<std::string> startup{"QT", "QT", "SCIP2.0", "BM", "HS0", "PP", "VV",
                                         "MD0000108001000"};
  ASSERT_GE(commands.size(), startup.size());
  EXPECT_TRUE(std::equal(startup.begin(), startup.end(), commands.begin()));
  EXPECT_EQ(commands.back(), "MD0000108001000");

  const auto obs = driver.collect(20, milliseconds(3000));
  ASSERT_EQ(obs.size(), 20u);
  EXPECT_EQ(driver.hardware_errors, 0u);
  EXPECT_TRUE(driver.errors.empty());
  const auto sent = emu.sentScans();
  std::vector<const SentScan*> match;
  size_t no_echo_total = 0;
  for (const auto& o : obs)
  {
    ASSERT_EQ(o.getScanSize(), 1081u);
    EXPECT_TRUE(o.rightToLeft);
    EXPECT_NEAR(o.aperture, 1081 * 2 * M_PI / 1440, 1e-6);  // 270.25 deg
    EXPECT_FLOAT_EQ(o.maxRange, 60.0f);
    match.push_back(matchSent(o, sent));
    ASSERT_TRUE(match.back()) << "an observation is not a scan the emulator sent";
    if (match.size() > 1)
    {
      EXPECT_EQ(match.back()->number, match[match.size() - 2]->number + 1) << "a scan was lost";
    }
    size_t no_echo = 0;
    for (size_t i = 0; i < o.getScanSize(); i++)
    {
      const uint32_t mm = match.back()->scan.ranges_mm[i];
      EXPECT_EQ(o.getScanRangeValidity(i), mm >= 20) << "beam " << i;
      no_echo += mm == kNoEcho;
    }
    EXPECT_LT(no_echo, o.getScanSize());  // the world is in sight
    no_echo_total += no_echo;
  }
  EXPECT_GT(no_echo_total, 0u);  // rays without return were sent, and read as invalid
  // From its 11th scan on, the driver stamps scans with the sensor's clock.
  for (size_t j = 11; j < obs.size(); j++)
  {
    const double dt = mrpt::system::timeDifference(obs[10].timestamp, obs[j].timestamp);
    EXPECT_NEAR(dt, (match[j]->timestamp_ms - match[10]->timestamp_ms) * 1e-3, 1e-6);
    EXPECT_NEAR(dt, (j - 10) * 0.025, 1e-6);
  }
}

TEST(HokuyoDriver, ReconnectsByItselfWhenTheSensorDropsTheConnection)
{
  EmulatorOptions opt;
  opt.faults.drop_after_scans = 8;
  ScipEmulator emu(utmSource(), opt);
  Driver driver(emu.port());
  driver.initialize();
  const auto obs = driver.collect(15, milliseconds(4000));
  ASSERT_EQ(obs.size(), 15u);
  EXPECT_TRUE(contains(driver.errors, "connection lost")) << "the drop was not reported";
  const auto s = emu.stats();
  EXPECT_EQ(s.connections, 2u);
  EXPECT_EQ(s.drops, 1u);
  const auto sent = emu.sentScans();
  const SentScan* last = matchSent(obs.back(), sent);
  ASSERT_TRUE(last);
  EXPECT_EQ(last->connection, 2u);
  for (const auto& o : obs) EXPECT_TRUE(matchSent(o, sent));
}

TEST(HokuyoDriver, ReportsAnUnreachableSensorAndReconnectsWhenItIsBack)
{
  const SimScanSource source = utmSource();
  auto emu = std::make_unique<ScipEmulator>(source);
  const uint16_t port = emu->port();
  Driver driver(port);
  driver.initialize();
  ASSERT_EQ(driver.collect(3, milliseconds(2000)).size(), 3u);

  emu.reset();  // the sensor is gone: connection closed, port closed
  EXPECT_TRUE(driver.collect(1, milliseconds(300)).empty());
  EXPECT_GT(driver.hardware_errors + driver.exceptions.size(), 0u)
      << "an unreachable sensor was not reported";

  // Back on the same port, the driver reconnects from doProcessSimple(). (Calling
  // initialize() again here may never return: MRPT keeps a stale socket after a failed
  // reconnection and spins writing to it.)
  EmulatorOptions opt;
  opt.port = port;
  emu = std::make_unique<ScipEmulator>(source, opt);
  const auto obs = driver.collect(5, milliseconds(3000));
  ASSERT_EQ(obs.size(), 5u);
  const auto sent = emu->sentScans();
  for (const auto& o : obs) EXPECT_TRUE(matchSent(o, sent));
  EXPECT_EQ(emu->stats().connections, 1u);
}

TEST(HokuyoDriver, MalformedScansAreReportedOrSkippedNeverCrash)
{
  ScipEmulator emu(utmSource());
  Driver driver(emu.port());
  driver.initialize();
  ASSERT_EQ(driver.collect(2, milliseconds(2000)).size(), 2u);
  const uint64_t n0 = emu.stats().scans_sent + 2;
  Faults faults;
  faults.scans = {{n0, Fault::BadChecksum}, {n0 + 3, Fault::TruncatedLine},
                  {n0 + 6, Fault::WrongEcho}};
  emu.setFaults(faults);
  ASSERT_TRUE(emu.waitFor([&](const EmulatorStats& s) { return s.scans_sent > n0 + 10; },
                          milliseconds(3000)));
  const auto obs = driver.collect(100, milliseconds(600));  // everything received so far
  const auto sent = emu.sentScans();
  std::vector<uint64_t> numbers;
  for (const auto& o : obs)
  {
    const SentScan* s = matchSent(o, sent);
    ASSERT_TRUE(s);
    numbers.push_back(s->number);
  }
  const auto got = [&](uint64_t n) { return std::count(numbers.begin(), numbers.end(), n) > 0; };
  EXPECT_TRUE(got(n0)) << "MRPT's driver does not check checksums: the scan comes through";
  EXPECT_FALSE(got(n0 + 3));
  EXPECT_GE(driver.hardware_errors, 1u) << "the truncated scan was not reported";
  EXPECT_TRUE(contains(driver.errors, "data bytes"));
  EXPECT_FALSE(got(n0 + 6)) << "a scan with a wrong echo is skipped";
  EXPECT_TRUE(got(n0 + 7) && got(n0 + 8)) << "the stream goes on after the faults";
}

TEST(HokuyoDriver, MalformedStartupReplyFailsInitializeThenRecovers)
{
  EmulatorOptions opt;
  opt.faults.replies = {{"PP", Fault::WrongEcho}};
  ScipEmulator emu(utmSource(), opt);
  Driver driver(emu.port());
  driver.initialize();
  EXPECT_TRUE(contains(driver.errors, "Error initializing"));
  EXPECT_TRUE(driver.collect(1, milliseconds(500)).empty());
  EXPECT_EQ(emu.stats().scans_sent, 0u);

  emu.setFaults({});
  driver.initialize();
  const auto obs = driver.collect(5, milliseconds(3000));
  ASSERT_EQ(obs.size(), 5u);
  for (const auto& o : obs) EXPECT_TRUE(matchSent(o, emu.sentScans()));
}

}  // namespace
TEST(HokuyoLink, ALinkThatPausesPastTheDriversTimeoutComesBack)
{
  // The link goes silent for 1.5 s after 20 scans, the sensor alive. MRPT's driver then takes
  // the link for dead, tries to reopen it as a serial port and throws on every poll: the link
  // must count that as a stall, drop the driver and connect a new one.
  EmulatorOptions opt;
  opt.faults.pause_after_scans = 20;
  opt.faults.pause_ms = 1500;
  ScipEmulator emu(utmSource(), opt);
  const mrpt::config::CConfigFileMemory cfg("[LASER_2D]\ndriver = CHokuyoURG\nsensorLabel = HOKUYO_UTM\n"
                                            "IP_DIR = 127.0.0.1\nPORT_DIR = " + std::to_string(emu.port()) + "\n");
  io::HokuyoLinkOptions lo;
  lo.stall_timeout = milliseconds(2000);  // the default: longer than the driver's own 1.1 s
  std::vector<std::string> log;
  io::HokuyoLink link(cfg, "LASER_2D", lo, [&](const std::string& m) { log.push_back(m); });
  size_t scans = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (scans < 60 && std::chrono::steady_clock::now() < deadline)
    if (link.poll()) scans++;
  std::string said;
  for (const auto& m : log) said += m + "\n";
  EXPECT_EQ(scans, 60u) << said;
  EXPECT_GE(link.stats().stalls, 1u) << said;
  EXPECT_GE(emu.stats().connections, 2u) << said;
}

namespace
{
/** The emulator's sensor section. */
mrpt::config::CConfigFileMemory sensorSection(uint16_t port)
{
  return mrpt::config::CConfigFileMemory("[LASER_2D]\ndriver = CHokuyoURG\nsensorLabel = HOKUYO_UTM\n"
                                         "IP_DIR = 127.0.0.1\nPORT_DIR = " + std::to_string(port) + "\n");
}

std::string joined(const std::vector<std::string>& lines)
{
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}
}  // namespace

TEST(HokuyoLink, ALinkSendingGarbageIsReportedCountedAndReconnected)
{
  // After 20 scans the first connection sends random bytes instead of SCIP. MRPT's driver
  // searched them for a reply forever (the poll never returned); now each poll reads for
  // poll_budget at most, the garbage is said and counted, and after stall_timeout the link
  // is replaced, the next connection streaming again.
  EmulatorOptions opt;
  opt.faults.garbage_after_scans = 20;
  ScipEmulator emu(utmSource(), opt);
  const auto cfg = sensorSection(emu.port());
  io::HokuyoLinkOptions lo;
  lo.stall_timeout = milliseconds(1000);
  std::vector<std::string> log;
  io::HokuyoLink link(cfg, "LASER_2D", lo, [&](const std::string& m) { log.push_back(m); });
  size_t scans = 0;
  auto longest = std::chrono::steady_clock::duration::zero();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (scans < 60 && std::chrono::steady_clock::now() < deadline)
  {
    const auto t = std::chrono::steady_clock::now();
    scans += link.poll() != nullptr;
    longest = std::max(longest, std::chrono::steady_clock::now() - t);
  }
  EXPECT_EQ(scans, 60u) << joined(log);
  EXPECT_LT(longest, milliseconds(800)) << "a poll read past its budget";
  const auto& s = link.stats();
  EXPECT_GT(s.garbage_bytes, 0u);
  EXPECT_LE(s.garbage_bytes, emu.stats().garbage_bytes);
  EXPECT_GE(s.stalls, 1u);
  EXPECT_EQ(emu.stats().connections, 2u);
  EXPECT_TRUE(contains(log, "not SCIP 2.0")) << joined(log);
  EXPECT_TRUE(contains(log, "receiving scans again")) << joined(log);
}

TEST(HokuyoLink, GarbageFromTheStartFailsEachConnectionWithinItsBudget)
{
  EmulatorOptions opt;
  opt.faults.garbage_after_scans = 0;
  opt.faults.garbage_connections = 1000;
  ScipEmulator emu(utmSource(), opt);
  const auto cfg = sensorSection(emu.port());
  io::HokuyoLinkOptions lo;
  lo.connect_budget = milliseconds(300);
  lo.max_backoff = milliseconds(250);
  std::vector<std::string> log;
  io::HokuyoLink link(cfg, "LASER_2D", lo, [&](const std::string& m) { log.push_back(m); });
  auto longest = std::chrono::steady_clock::duration::zero();
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  size_t scans = 0;
  while (std::chrono::steady_clock::now() < end)
  {
    const auto t = std::chrono::steady_clock::now();
    scans += link.poll() != nullptr;
    longest = std::max(longest, std::chrono::steady_clock::now() - t);
  }
  EXPECT_EQ(scans, 0u);
  EXPECT_LT(longest, milliseconds(600));
  EXPECT_GE(link.stats().errors, 2u);  // every attempt failed, and was retried
  EXPECT_GE(emu.stats().connections, 2u);
  EXPECT_GT(link.stats().garbage_bytes, 0u);
  EXPECT_TRUE(contains(log, "initialization failed: the link sends data that is not SCIP 2.0")) << joined(log);
}

TEST(HokuyoLink, AStopEndsAPollInsideTheDriverAndIsNotAFailure)
{
  EmulatorOptions opt;
  opt.faults.garbage_after_scans = 0;
  ScipEmulator emu(utmSource(), opt);
  const auto cfg = sensorSection(emu.port());
  io::HokuyoLinkOptions lo;
  lo.connect_budget = lo.poll_budget = milliseconds(20000);  // only the stop can end it
  const auto stop_at = std::chrono::steady_clock::now() + milliseconds(300);
  lo.stop = [&] { return std::chrono::steady_clock::now() >= stop_at; };
  std::vector<std::string> log;
  auto link = std::make_unique<io::HokuyoLink>(cfg, "LASER_2D", lo, [&](const std::string& m) { log.push_back(m); });
  EXPECT_FALSE(link->poll());
  const auto took = std::chrono::steady_clock::now() - stop_at;
  EXPECT_LT(took, milliseconds(300));
  EXPECT_GT(emu.stats().garbage_bytes, 0u);
  EXPECT_EQ(link->stats().errors, 0u);
  EXPECT_EQ(link->stats().driver_messages, 0u);
  EXPECT_TRUE(log.empty()) << joined(log);
  const auto t = std::chrono::steady_clock::now();
  link.reset();  // its driver shuts down without waiting on the garbage
  EXPECT_LT(std::chrono::steady_clock::now() - t, milliseconds(300));
}

}  // namespace swslam::scip
