#pragma once
// A TCP connection as an mrpt::io::CStream for MRPT's sensor drivers (bindIO), which never
// blocks for long and never spins: reads wait at most `read_timeout` and return what came,
// writes go out with MSG_NOSIGNAL. Once the peer closes or the link fails the stream is
// dead(): reads return nothing and writes are dropped (reported as written, so that a
// driver's shut-down commands cannot throw from its destructor). MRPT 2.5's own socket
// (CClientTCPSocket::Write) loops forever on a failed send, which can hang a driver.
//
// Reads can also be limited in time (limitReads) and stopped (setStop): MRPT 2.5's Hokuyo
// driver searches the incoming bytes for its reply for as long as bytes come, so a peer
// that streams garbage keeps a driver call reading forever; a read past the limit, or
// once the stop holds, returns nothing at once, which ends the call as a timeout would.

#include <mrpt/io/CStream.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

namespace swslam::io
{
class TcpStream : public mrpt::io::CStream
{
 public:
  /** Connects; throws std::runtime_error naming the address if it cannot within
   * `connect_timeout`. */
  TcpStream(const std::string& host, int port, std::chrono::milliseconds connect_timeout,
            std::chrono::milliseconds read_timeout);
  ~TcpStream() override;
  TcpStream(const TcpStream&) = delete;
  TcpStream& operator=(const TcpStream&) = delete;

  size_t Read(void* buffer, size_t count) override;
  size_t Write(const void* buffer, size_t count) override;
  uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override { return 0; }
  uint64_t getTotalBytesCount() const override { return 0; }
  uint64_t getPosition() const override { return 0; }
  std::string getStreamDescription() const override { return "tcp " + address_; }

  /** Reads from `deadline` on return nothing at once; cut() says whether one did since. */
  void limitReads(std::chrono::steady_clock::time_point deadline);
  bool cut() const { return cut_; }
  /** While `stop()` holds, reads return nothing at once (and count as cut). */
  void setStop(std::function<bool()> stop) { stop_ = std::move(stop); }
  /** Bytes received so far. */
  uint64_t bytesRead() const { return bytes_read_; }

  /** The peer closed or the link failed; why() says how. */
  bool dead() const { return dead_; }
  std::string why() const;

 private:
  void die(const std::string& why);

  std::string address_;
  int fd_ = -1;
  std::chrono::milliseconds read_timeout_;
  std::chrono::steady_clock::time_point read_deadline_ = std::chrono::steady_clock::time_point::max();
  std::function<bool()> stop_;
  bool cut_ = false;
  uint64_t bytes_read_ = 0;
  std::atomic<bool> dead_{false};
  std::string why_;
};

}  // namespace swslam::io
