// swslam-scip-emulator: serves a simulator scenario as a Hokuyo UTM-30LX (SCIP 2.0 over
// TCP) for manual and script tests. Not installed. See doc/live.md, "SCIP emulator".
#include "cli.h"
#include "scip_emulator.h"
#include "scip_sim_source.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <ctime>
#include <iostream>

namespace
{
/** "A:B" split at the first ':'; throws naming the option. */
std::pair<std::string, std::string> splitPair(const std::string& s, const std::string& option)
{
  const size_t colon = s.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("--" + option + " '" + s + "': expected KEY:FAULT");
  return {s.substr(0, colon), s.substr(colon + 1)};
}
}  // namespace

int main(int argc, char** argv)
{
  using namespace swslam::scip;
  TCLAP::CmdLine cmd("swslam-scip-emulator: a simulated UTM-30LX on a TCP port", ' ', "0.1");
  TCLAP::ValueArg<std::string> scenario("s", "scenario", "Scenario .ini file", true, "",
                                        "FILE.ini", cmd);
  TCLAP::ValueArg<std::string> address("a", "address", "IPv4 address to listen on", false,
                                       "127.0.0.1", "IP", cmd);
  TCLAP::ValueArg<unsigned> port("p", "port", "TCP port (0: any free one, printed)", false,
                                 10940, "PORT", cmd);
  TCLAP::ValueArg<double> duration("d", "duration", "Seconds to serve (0: until SIGINT/SIGTERM)",
                                   false, 0, "SEC", cmd);
  TCLAP::ValueArg<unsigned> drop_after("", "drop-after",
                                       "Close a connection after this many scans", false, 0,
                                       "N", cmd);
  TCLAP::ValueArg<unsigned> drops("", "drops", "Connections dropped by --drop-after", false, 1,
                                  "N", cmd);
  TCLAP::ValueArg<unsigned> garbage_after(
      "", "garbage-after", "Send random bytes instead of SCIP once a connection got N scans (0: from its start)",
      false, 0, "N", cmd);
  TCLAP::ValueArg<unsigned> garbage_connections("", "garbage-connections",
                                                "Connections that --garbage-after turns to garbage",
                                                false, 1, "N", cmd);
  TCLAP::MultiArg<std::string> scan_faults(
      "", "scan-fault", "Malformed scan: NUMBER:bad-checksum|truncated-line|wrong-echo", false,
      "N:FAULT", cmd);
  TCLAP::MultiArg<std::string> reply_faults(
      "", "reply-fault", "Malformed replies to a command: CODE:FAULT, e.g. PP:bad-checksum",
      false, "CODE:FAULT", cmd);
  try
  {
    if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
    if (port.getValue() > 65535) throw std::invalid_argument("--port: above 65535");
    if (duration.getValue() < 0) throw std::invalid_argument("--duration: negative");
    EmulatorOptions opt;
    opt.address = address.getValue();
    opt.port = static_cast<uint16_t>(port.getValue());
    opt.faults.drop_after_scans = drop_after.getValue();
    opt.faults.drops = drops.getValue();
    if (garbage_after.isSet()) opt.faults.garbage_after_scans = garbage_after.getValue();
    opt.faults.garbage_connections = garbage_connections.getValue();
    for (const auto& f : scan_faults.getValue())
    {
      const auto [number, fault] = splitPair(f, "scan-fault");
      opt.faults.scans[std::stoull(number)] = parseFault(fault);
    }
    for (const auto& f : reply_faults.getValue())
    {
      const auto [code, fault] = splitPair(f, "reply-fault");
      opt.faults.replies[code] = parseFault(fault);
    }
    const SimScanSource source(swslam::sim::loadScenario(scenario.getValue()), opt.sensor);

    // The emulator's thread inherits the blocked signals: only this thread waits for them.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    ScipEmulator emulator(source, opt);
    std::cout << "swslam-scip-emulator: " << opt.sensor.model << " on " << opt.address << ":"
              << emulator.port() << ", " << source.pathScans() << " scans along the path at "
              << source.rate() << " Hz" << std::endl;
    // Until SIGINT/SIGTERM or the end of the duration. A stop and continue (SIGSTOP, SIGCONT)
    // interrupts the wait (EINTR): wait again, for what is left.
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(duration.getValue());
    for (;;)
    {
      int got = 0;
      if (duration.getValue() > 0)
      {
        const double left = std::chrono::duration<double>(end - std::chrono::steady_clock::now()).count();
        if (left <= 0) break;
        timespec ts{};
        ts.tv_sec = static_cast<time_t>(left);
        ts.tv_nsec = static_cast<long>((left - static_cast<double>(ts.tv_sec)) * 1e9);
        got = sigtimedwait(&signals, nullptr, &ts);
      }
      else
        got = sigwaitinfo(&signals, nullptr);
      if (got >= 0 || errno != EINTR) break;  // a signal, or the duration is over (EAGAIN)
    }
    emulator.stop();
    const auto s = emulator.stats();
    std::cout << "swslam-scip-emulator: " << s.connections << " connections, " << s.scans_sent
              << " scans sent, " << s.commands.size() << " commands"
              << (s.garbage_bytes ? ", " + std::to_string(s.garbage_bytes) + " bytes of garbage" : "")
              << (s.error.empty() ? "" : ", error: " + s.error) << std::endl;
    return s.error.empty() ? 0 : 1;
  }
  catch (const TCLAP::ArgException& e)
  {
    std::cerr << "swslam-scip-emulator: " << e.error() << " (" << e.argId() << ")\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-scip-emulator: " << e.what() << "\n";
  }
  return 1;
}
