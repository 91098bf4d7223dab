#pragma once
// A SCIP 2.0 sensor on a TCP port, for tests: it answers the commands of one client at a
// time (a new connection replaces the current one) and, while an MD/ME request is active,
// streams one scan per scan period (40 Hz for a UTM-30LX), taken from a ScanSource.
// Scan k is the sensor's k-th period since the emulator started (t = k / rate), so a
// client that connects late or reconnects sees the scene where it is at that time; its
// timestamp is first_timestamp_ms + k * period, in ms, modulo 2^24.
// The server runs on its own thread ("scip-emulator"), woken by its sockets, the scan
// clock or the caller (eventfd); the destructor stops and joins it.

#include "scip_frame.h"
#include "scip_protocol.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace swslam::scip
{
/** The ranges of scan k (called on the emulator's thread, for the scans it sends). */
using ScanSource = std::function<Scan(uint64_t k)>;

/** Random bytes sent per scan period by a connection gone to garbage (a scan frame is ~3.4 kB). */
constexpr size_t kGarbagePerPeriod = 3400;

/** Malformed or interrupted replies, on purpose. */
struct Faults
{
  uint64_t drop_after_scans = 0;  ///< close a connection once it got this many scans (0: never)
  unsigned drops = 1;             ///< connections dropped that way; later ones stream on
  bool drop_mid_frame = false;    ///< the last scan before a drop is cut half way
  /** The link goes silent once a connection got this many scans (0: never), the sensor alive:
   * for pause_ms nothing is sent (the scans of that time are lost), then streaming goes on. */
  uint64_t pause_after_scans = 0;
  unsigned pause_ms = 0;
  /** A connection streams random bytes instead of SCIP once it got this many scans (0: from
   * its start; unset: never): every scan period about a scan's worth (kGarbagePerPeriod), no
   * replies, until it closes; for the first `garbage_connections` connections. */
  std::optional<uint64_t> garbage_after_scans;
  unsigned garbage_connections = 1;
  /** Faults of the scans sent, by their number (0-based, counted over all connections). */
  std::map<uint64_t, Fault> scans;
  /** Faults of every reply to a command, by its two-letter code ("PP", "MD", "QT", ...;
   * the scans an MD/ME request streams are not replies: see `scans`). */
  std::map<std::string, Fault> replies;
};

struct EmulatorOptions
{
  std::string address = "127.0.0.1";  ///< IPv4 address to listen on
  uint16_t port = 0;                  ///< 0: any free port (see ScipEmulator::port())
  SensorInfo sensor;                  ///< PP values; the scan rate is sensor.scanRate()
  uint32_t first_timestamp_ms = 0;    ///< timestamp of scan 0 (e.g. near 2^24 to test the wrap)
  size_t history = 512;               ///< sent scans kept for sentScans()
  Faults faults;
};

/** A scan the emulator sent. */
struct SentScan
{
  uint64_t number = 0;      ///< 0-based over the emulator's life
  uint64_t k = 0;           ///< scan period (argument of the source)
  uint32_t timestamp_ms = 0;
  uint64_t connection = 0;  ///< 1-based number of the connection it was sent on
  Fault fault = Fault::None;
  Scan scan;                ///< as the source gave it (every step)
};

struct EmulatorStats
{
  uint64_t connections = 0;  ///< accepted so far
  uint64_t drops = 0;        ///< connections closed by the emulator (faults or dropConnection())
  uint64_t disconnects = 0;  ///< connections closed by the client
  uint64_t scans_sent = 0;
  uint64_t garbage_bytes = 0;  ///< random bytes sent (Faults::garbage_after_scans)
  bool client_connected = false;
  bool streaming = false;    ///< an MD/ME request is active on the current connection
  std::vector<std::string> commands;  ///< every command line received, in order
  std::string error;         ///< first failure of the source (the connection was closed)
};

class ScipEmulator
{
 public:
  /** Listens (throws std::runtime_error if it cannot) and starts the server thread. */
  ScipEmulator(ScanSource source, EmulatorOptions options = {});
  ~ScipEmulator();
  ScipEmulator(const ScipEmulator&) = delete;
  ScipEmulator& operator=(const ScipEmulator&) = delete;

  uint16_t port() const { return port_; }
  const EmulatorOptions& options() const { return opt_; }

  /** Stops the server and joins its thread (also done by the destructor). */
  void stop();
  /** Closes the current client connection, if any; the next one is accepted. */
  void dropConnection();
  /** Replaces the faults (counts of drops start again). */
  void setFaults(const Faults& faults);

  EmulatorStats stats() const;
  std::vector<SentScan> sentScans() const;

  /** Waits until `pred(stats())` holds or `timeout` passes; returns whether it holds. */
  bool waitFor(const std::function<bool(const EmulatorStats&)>& pred,
               std::chrono::milliseconds timeout) const;

 private:
  struct Connection;
  ScanSource source_;
  EmulatorOptions opt_;
  int listen_fd_ = -1, wake_fd_ = -1;
  uint16_t port_ = 0;
  Protocol protocol_;  // server thread only

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  EmulatorStats stats_;             // guarded by mutex_
  std::vector<SentScan> history_;   // guarded by mutex_ (ring of opt_.history)
  Faults faults_;                   // guarded by mutex_
  unsigned drops_done_ = 0;         // guarded by mutex_
  unsigned garbage_done_ = 0;       // guarded by mutex_
  bool stop_requested_ = false;     // guarded by mutex_
  bool drop_requested_ = false;     // guarded by mutex_
  std::thread thread_;

  void run();
  void wake();
  void handleInput(Connection& c);
  void sendScan(Connection& c, uint64_t k);
  /** Whether connection `c`, having got its scans, turns to garbage now (counted). */
  bool startsGarbage(const Connection& c);
  void sendGarbage(Connection& c, uint64_t periods);
  void closeConnection(Connection& c, bool by_emulator);
};

}  // namespace swslam::scip
