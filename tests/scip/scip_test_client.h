#pragma once
// A minimal blocking SCIP client over TCP for tests of the emulator: it sends command
// lines and reads whole frames (checksums checked by parseFrame), with timeouts.

#include "scip_frame.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace swslam::scip
{
class TestClient
{
 public:
  /** Connects to 127.0.0.1:port; throws std::runtime_error on failure. */
  explicit TestClient(uint16_t port);
  ~TestClient();
  TestClient(const TestClient&) = delete;
  TestClient& operator=(const TestClient&) = delete;

  /** Sends `command` followed by LF. */
  void send(const std::string& command);
  /** The next frame, or nothing if none is complete within `timeout` or the peer closed. */
  std::optional<ParsedFrame> readFrame(std::chrono::milliseconds timeout);
  /** The next frame whose echo starts with `prefix`, skipping others (e.g. scans in
   * flight before a QT reply). */
  std::optional<ParsedFrame> readFrameEchoing(const std::string& prefix,
                                              std::chrono::milliseconds timeout);
  /** Whether the peer closed the connection within `timeout` (data read meanwhile is
   * kept). */
  bool waitClosed(std::chrono::milliseconds timeout);
  /** Bytes received and not parsed yet. */
  const std::string& pending() const { return in_; }

 private:
  int fd_ = -1;
  bool closed_ = false;
  std::string in_;

  /** Reads what arrives before `deadline`; false on timeout or close. */
  bool receive(std::chrono::steady_clock::time_point deadline);
};

}  // namespace swslam::scip
