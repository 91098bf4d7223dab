#pragma once
// The connection to a Hokuyo through MRPT's CHokuyoURG driver, kept alive: it configures the
// driver from an MRPT rawlog-grabber-style section ([LASER_2D], driver = CHokuyoURG, the
// driver's own keys), polls it for scans, and when the sensor stops answering or the link
// drops, says so and reconnects with a growing backoff, for as long as it is polled.
//
// MRPT 2.5's driver, as observed against tests/scip's emulator: its own TCP socket can spin
// forever on a failed write (after a drop, inside doProcessSimple()), so over Ethernet the
// driver is bound (bindIO) to swslam's TcpStream, which never blocks for long; a lost link
// or a silent sensor then replaces the driver and its connection, retried with a growing
// backoff. Over serial the driver's own port handling is used (it reopens the port by
// itself), after checking that the device exists. Errors the driver logs are forwarded.
// The driver searches the incoming bytes for its reply for as long as bytes come, so over
// Ethernet each of its calls may read for a limited time only, and stops reading when told
// to. Data that is not SCIP 2.0 (a peer sending garbage: a call cut at its budget while data
// kept coming, or more than 32 KiB without a scan; io/garbage_meter.h) is reported, counted,
// and otherwise handled as a silent sensor (a stall, then a new connection).

#include <swslam/io/garbage_meter.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace mrpt::hwdrivers
{
class CHokuyoURG;
}

namespace swslam::io
{
class TcpStream;

struct HokuyoLinkOptions
{
  std::chrono::milliseconds stall_timeout{2000};   ///< no scan this long: reported as stopped answering
  std::chrono::milliseconds min_backoff{250};      ///< first wait before reconnecting...
  std::chrono::milliseconds max_backoff{4000};     ///< ...doubling up to this
  /** Longest a poll may read (Ethernet): longer than a scan takes to come and arrive. */
  std::chrono::milliseconds poll_budget{500};
  /** Longest a connection's start-up sequence may read (Ethernet; it takes ~1 ms). */
  std::chrono::milliseconds connect_budget{2000};
  /** Polled while the driver reads: once it holds, a poll in progress returns at once
   * (Ethernet; e.g. the run was asked to stop). */
  std::function<bool()> stop;
};

/** Counts of what happened on the link. */
struct HokuyoLinkStats
{
  size_t scans = 0, connects = 0, errors = 0, stalls = 0;
  size_t attempts = 0;  ///< connections tried (each reachability check or initialization)
  size_t driver_messages = 0;  ///< error messages the driver logged
  uint64_t garbage_bytes = 0;  ///< bytes of data that was not SCIP 2.0 (see GarbageMeter)
  bool connected = false;  ///< a scan arrived since the last (re)connection
};

/** Throws std::invalid_argument naming the problem if `section` is missing, its driver is not
 * CHokuyoURG, a key is not one the driver or MRPT's sensor base reads, or neither (or both)
 * of a serial port and an IP address is given. */
void checkHokuyoSection(const mrpt::config::CConfigFileBase& cfg, const std::string& section);

class HokuyoLink
{
 public:
  using Log = std::function<void(const std::string&)>;
  HokuyoLink(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
             HokuyoLinkOptions options, Log log);
  ~HokuyoLink();  ///< the driver is shut down without waiting on the link

  /** The next scan, or nullptr if none arrived within about the driver's timeout (or while
   * waiting to reconnect: the wait is cut in steps of at most 100 ms, so a caller can stop). */
  mrpt::obs::CObservation2DRangeScan::Ptr poll();

  const HokuyoLinkStats& stats() const { return stats_; }
  /** Where the sensor is: "IP:PORT" (Ethernet) or the serial port. */
  std::string address() const;
  /** How the link retries: "reconnecting after 250 ms, doubling up to 4000 ms, for as long as
   * the run lasts". */
  std::string retryPolicy() const;

 private:
  /** No driver: connects once the backoff has passed; false (and the retry set) if not. */
  bool connectWhenDue();
  /** A scan came: the outage (if any) ends, the counters and the backoff reset. */
  void scanReceived();
  bool reachable(std::string& why) const;
  bool connect(std::string& why);  ///< false (driver dropped, `why` set) if initialize() failed
  void trouble(const std::string& why);     ///< reported once per outage
  void retryLater(const std::string& why);  ///< no driver: try again after the backoff
  void dropDriver();
  /** No scan for stall_timeout: count a stall and start over. */
  void checkStall();
  /** Limits the driver's reads to `budget` from now; returns the bytes read so far. */
  uint64_t limitReads(std::chrono::milliseconds budget);
  /** After a driver call that gave no scan (its reads limited when it read `bytes_before`):
   * what to say if the link turned out to carry garbage (else ""). */
  std::string garbage(uint64_t bytes_before);
  bool stopping() const { return options_.stop && options_.stop(); }

  std::string ini_text_, ini_without_link_, section_;
  std::shared_ptr<TcpStream> stream_;  ///< Ethernet link (serial: the driver's own port)
  std::string stream_why_;
  std::string ip_, serial_;
  int port_ = 10940;
  HokuyoLinkOptions options_;
  Log log_;
  std::unique_ptr<mrpt::hwdrivers::CHokuyoURG> driver_;
  HokuyoLinkStats stats_;
  GarbageMeter garbage_meter_{32 * 1024};
  static constexpr size_t kMaxDriverMessages = 5;  ///< printed per outage (all counted)
  size_t driver_messages_this_outage_ = 0;
  std::string last_driver_message_;
  bool in_outage_ = false;
  bool dropping_ = false;
  std::chrono::steady_clock::time_point outage_start_;
  std::chrono::milliseconds backoff_;
  std::chrono::steady_clock::time_point last_scan_, retry_at_;
};

}  // namespace swslam::io
