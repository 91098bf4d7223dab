#include "scip_emulator.h"

#include "scip_encoding.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>

namespace swslam::scip
{
namespace
{
using Clock = std::chrono::steady_clock;
constexpr size_t kMaxPendingOutput = 1 << 20;  ///< scans are not queued beyond this
constexpr size_t kMaxCommandLength = 4096;     ///< longer input without LF is discarded
constexpr uint64_t kMaxCatchUp = 8;            ///< late scan periods still sent

std::runtime_error systemError(const std::string& what)
{
  return std::runtime_error("SCIP emulator: " + what + ": " + std::strerror(errno));
}

/** Faults::pause_after_scans: once over the emulator's life, the link goes silent. */
class LinkPause
{
 public:
  /** True while the link is silent: from when a connection got `after` scans (0: never), for
   * `ms` milliseconds. */
  bool silent(uint64_t after, unsigned ms, uint64_t scans, Clock::time_point now)
  {
    if (after && scans >= after && !started_)
    {
      started_ = true;
      end_ = now + std::chrono::milliseconds(ms);
    }
    return started_ && now < end_;
  }

 private:
  bool started_ = false;
  Clock::time_point end_;
};
}  // namespace

struct ScipEmulator::Connection
{
  int fd = -1;
  uint64_t number = 0;
  uint64_t scans = 0;    ///< scans sent on this connection
  bool closing = false;  ///< closes once the output is flushed
  bool garbage = false;  ///< sends random bytes instead of SCIP (Faults::garbage_after_scans)
  std::mt19937 random;   ///< its bytes, seeded with the connection's number
  std::string in, out;
};

ScipEmulator::ScipEmulator(ScanSource source, EmulatorOptions options)
    : source_(std::move(source)), opt_(std::move(options)), protocol_(opt_.sensor)
{
  if (!source_) throw std::invalid_argument("SCIP emulator: no scan source");
  faults_ = opt_.faults;
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) throw systemError("socket");
  const int yes = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(opt_.port);
  if (::inet_pton(AF_INET, opt_.address.c_str(), &addr.sin_addr) != 1)
  {
    ::close(listen_fd_);
    throw std::invalid_argument("SCIP emulator: '" + opt_.address + "' is not an IPv4 address");
  }
  socklen_t len = sizeof addr;
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
      ::listen(listen_fd_, 4) != 0 ||
      ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len) != 0)
  {
    const auto e = systemError("cannot listen on " + opt_.address + ":" + std::to_string(opt_.port));
    ::close(listen_fd_);
    throw e;
  }
  port_ = ntohs(addr.sin_port);
  wake_fd_ = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (wake_fd_ < 0)
  {
    ::close(listen_fd_);
    throw systemError("eventfd");
  }
  thread_ = std::thread([this] { run(); });
}

ScipEmulator::~ScipEmulator()
{
  stop();
  ::close(listen_fd_);
  ::close(wake_fd_);
}

void ScipEmulator::wake()
{
  const uint64_t one = 1;
  [[maybe_unused]] const auto n = ::write(wake_fd_, &one, sizeof one);
}

void ScipEmulator::stop()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_requested_ = true;
  }
  wake();
  if (thread_.joinable()) thread_.join();
}

void ScipEmulator::dropConnection()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    drop_requested_ = true;
  }
  wake();
}

void ScipEmulator::setFaults(const Faults& faults)
{
  std::lock_guard<std::mutex> lock(mutex_);
  faults_ = faults;
  drops_done_ = 0;
  garbage_done_ = 0;
}

EmulatorStats ScipEmulator::stats() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

std::vector<SentScan> ScipEmulator::sentScans() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return history_;
}

bool ScipEmulator::waitFor(const std::function<bool(const EmulatorStats&)>& pred,
                           std::chrono::milliseconds timeout) const
{
  std::unique_lock<std::mutex> lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return pred(stats_); });
}

void ScipEmulator::closeConnection(Connection& c, bool by_emulator)
{
  ::close(c.fd);
  c = Connection{};
  protocol_.reset();
  std::lock_guard<std::mutex> lock(mutex_);
  (by_emulator ? stats_.drops : stats_.disconnects)++;
}

void ScipEmulator::handleInput(Connection& c)
{
  size_t lf;
  while (!c.closing && (lf = c.in.find('\n')) != std::string::npos)
  {
    const std::string line = c.in.substr(0, lf);
    c.in.erase(0, lf + 1);
    Fault fault = Fault::None;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stats_.commands.push_back(line);
      const auto it = faults_.replies.find(line.substr(0, 2));
      if (it != faults_.replies.end()) fault = it->second;
    }
    if (c.garbage) continue;  // commands are heard, not answered
    if (const auto frame = protocol_.reply(line)) c.out += serialize(*frame, fault);
  }
  if (c.in.size() > kMaxCommandLength) c.in.clear();
}

bool ScipEmulator::startsGarbage(const Connection& c)
{
  // The caller holds mutex_.
  const auto& after = faults_.garbage_after_scans;
  if (c.garbage || !after || c.scans < *after || garbage_done_ >= faults_.garbage_connections)
    return false;
  garbage_done_++;
  return true;
}

void ScipEmulator::sendGarbage(Connection& c, uint64_t periods)
{
  const size_t n = std::min<uint64_t>(periods, kMaxCatchUp) * kGarbagePerPeriod;
  if (c.out.size() > kMaxPendingOutput) return;  // the client does not read
  std::uniform_int_distribution<int> byte(0, 255);
  for (size_t i = 0; i < n; i++) c.out += static_cast<char>(byte(c.random));
  std::lock_guard<std::mutex> lock(mutex_);
  stats_.garbage_bytes += n;
}

void ScipEmulator::sendScan(Connection& c, uint64_t k)
{
  if (c.out.size() > kMaxPendingOutput) return;  // the client does not read: the scan is lost
  const double period_ms = 1000.0 / opt_.sensor.scanRate();
  const auto stamp = static_cast<uint32_t>(
      (opt_.first_timestamp_ms + static_cast<uint64_t>(std::llround(k * period_ms))) %
      kTimestampModulo);
  SentScan sent;
  Frame frame;
  try
  {
    sent.scan = source_(k);
    frame = protocol_.scanFrame(sent.scan, stamp);
  }
  catch (const std::exception& e)
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stats_.error.empty()) stats_.error = "scan " + std::to_string(k) + ": " + e.what();
    }
    closeConnection(c, true);
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  sent.number = stats_.scans_sent++;
  sent.k = k;
  sent.timestamp_ms = stamp;
  sent.connection = c.number;
  if (const auto it = faults_.scans.find(sent.number); it != faults_.scans.end())
    sent.fault = it->second;
  std::string bytes = serialize(frame, sent.fault);
  c.scans++;
  c.garbage = startsGarbage(c);  // after this scan
  if (faults_.drop_after_scans && c.scans >= faults_.drop_after_scans &&
      drops_done_ < faults_.drops)
  {
    drops_done_++;
    if (faults_.drop_mid_frame) bytes.resize(bytes.size() / 2);
    c.closing = true;
  }
  c.out += bytes;
  if (opt_.history)
  {
    if (history_.size() >= opt_.history) history_.erase(history_.begin());
    history_.push_back(std::move(sent));
  }
}

void ScipEmulator::run()
{
  pthread_setname_np(pthread_self(), "scip-emulator");
  const auto t0 = Clock::now();
  const std::chrono::duration<double> period(1.0 / opt_.sensor.scanRate());
  const auto periodOf = [&](Clock::time_point t) {
    return static_cast<uint64_t>(std::floor((t - t0) / period));
  };
  uint64_t next_k = 1;  // the first scan period not yet due
  Connection c;
  LinkPause pause;

  for (;;)
  {
    bool drop = false;
    uint64_t pause_after = 0;
    unsigned pause_ms = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stop_requested_) break;
      drop = drop_requested_;
      drop_requested_ = false;
      pause_after = faults_.pause_after_scans;
      pause_ms = faults_.pause_ms;
    }
    if (drop && c.fd >= 0) closeConnection(c, true);
    const bool ticking = c.fd >= 0 && !c.closing && (c.garbage || protocol_.measurement());
    int timeout_ms = -1;
    if (ticking)
    {
      const auto due = t0 + std::chrono::duration_cast<Clock::duration>(next_k * period);
      const auto wait = std::chrono::ceil<std::chrono::milliseconds>(due - Clock::now());
      timeout_ms = static_cast<int>(std::max<int64_t>(0, wait.count()));
    }
    const int polled = c.fd;
    pollfd fds[3] = {{wake_fd_, POLLIN, 0}, {listen_fd_, POLLIN, 0}, {c.fd, 0, 0}};
    if (c.fd >= 0) fds[2].events = static_cast<short>(POLLIN | (c.out.empty() ? 0 : POLLOUT));
    if (::poll(fds, c.fd >= 0 ? 3 : 2, timeout_ms) < 0 && errno != EINTR) break;

    if (fds[0].revents & POLLIN)
    {
      uint64_t n;
      [[maybe_unused]] const auto r = ::read(wake_fd_, &n, sizeof n);
    }
    if (fds[1].revents & POLLIN)
    {
      const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd >= 0)
      {
        if (c.fd >= 0) closeConnection(c, false);  // a new connection replaces the current one
        protocol_.reset();
        c = Connection{};
        c.fd = fd;
        std::lock_guard<std::mutex> lock(mutex_);
        c.number = ++stats_.connections;
        c.random.seed(static_cast<std::mt19937::result_type>(c.number));
        c.garbage = startsGarbage(c);  // from the start
      }
    }
    if (c.fd >= 0 && c.fd == polled && (fds[2].revents & (POLLIN | POLLHUP | POLLERR)))
    {
      char buf[4096];
      const ssize_t n = ::recv(c.fd, buf, sizeof buf, 0);
      if (n > 0)
      {
        c.in.append(buf, static_cast<size_t>(n));
        handleInput(c);
      }
      else if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR))
        closeConnection(c, false);
    }

    const auto now = Clock::now();
    if (pause.silent(pause_after, pause_ms, c.scans, now))  // nothing goes out, scans are lost
    {
      next_k = periodOf(now) + 1;
      continue;
    }
    if (c.fd >= 0 && !c.closing && c.garbage)
    {
      const uint64_t due = periodOf(now);
      if (due >= next_k) sendGarbage(c, due + 1 - next_k);
      next_k = std::max(next_k, due + 1);
    }
    else if (c.fd >= 0 && !c.closing && protocol_.measurement())
    {
      // Every due period gets its scan, late ones too (as a sensor's buffer would send
      // them); after a stall of more than kMaxCatchUp periods the older ones are lost.
      const uint64_t due = periodOf(now);
      if (due >= next_k + kMaxCatchUp) next_k = due + 1 - kMaxCatchUp;
      for (; next_k <= due && c.fd >= 0 && !c.closing && protocol_.measurement() && !c.garbage;
           next_k++)
        if (protocol_.scanDue()) sendScan(c, next_k);
    }
    else
      next_k = periodOf(now) + 1;  // a request starts streaming at the next period

    if (c.fd >= 0 && !c.out.empty())
    {
      const ssize_t n = ::send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
      if (n > 0)
        c.out.erase(0, static_cast<size_t>(n));
      else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
        closeConnection(c, false);
    }
    if (c.fd >= 0 && c.closing && c.out.empty()) closeConnection(c, true);

    std::lock_guard<std::mutex> lock(mutex_);
    stats_.client_connected = c.fd >= 0;
    stats_.streaming = c.fd >= 0 && protocol_.measurement().has_value();
    changed_.notify_all();
  }
  if (c.fd >= 0) ::close(c.fd);
  std::lock_guard<std::mutex> lock(mutex_);
  stats_.client_connected = stats_.streaming = false;
  changed_.notify_all();
}

}  // namespace swslam::scip
