#include <swslam/io/tcp_stream.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace swslam::io
{
TcpStream::TcpStream(const std::string& host, int port, std::chrono::milliseconds connect_timeout,
                     std::chrono::milliseconds read_timeout)
    : address_(host + ":" + std::to_string(port)), read_timeout_(read_timeout)
{
  addrinfo hints{}, *res = nullptr;
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &res) != 0 || !res)
    throw std::runtime_error("cannot resolve " + address_);
  fd_ = ::socket(res->ai_family, res->ai_socktype, res->ai_protocol);
  if (fd_ < 0)
  {
    freeaddrinfo(res);
    throw std::runtime_error("cannot create a socket for " + address_);
  }
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
  int rc = ::connect(fd_, res->ai_addr, res->ai_addrlen);
  freeaddrinfo(res);
  if (rc != 0 && errno == EINPROGRESS)
  {
    pollfd p{fd_, POLLOUT, 0};
    rc = ::poll(&p, 1, static_cast<int>(connect_timeout.count())) == 1 ? 0 : -1;
    int err = 0;
    socklen_t len = sizeof(err);
    if (rc == 0 && (::getsockopt(fd_, SOL_SOCKET, SO_ERROR, &err, &len) != 0 || err != 0)) rc = -1;
  }
  if (rc != 0)
  {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("no connection to " + address_);
  }
}

TcpStream::~TcpStream()
{
  if (fd_ >= 0) ::close(fd_);
}

void TcpStream::die(const std::string& why)
{
  if (!dead_) why_ = why;
  dead_ = true;
}

std::string TcpStream::why() const { return why_; }

void TcpStream::limitReads(std::chrono::steady_clock::time_point deadline)
{
  read_deadline_ = deadline;
  cut_ = false;
}

size_t TcpStream::Read(void* buffer, size_t count)
{
  if (dead_ || count == 0) return 0;
  const auto now = std::chrono::steady_clock::now();
  if (now >= read_deadline_ || (stop_ && stop_()))
  {
    cut_ = true;
    return 0;
  }
  // The wait ends at the limit too (rounded up: a wait of 0 ms would spin); a wait that ends
  // there without data is cut as well.
  const bool to_limit = read_deadline_ - now < read_timeout_;
  const auto wait = to_limit ? std::chrono::ceil<std::chrono::milliseconds>(read_deadline_ - now) : read_timeout_;
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, static_cast<int>(wait.count())) != 1)
  {
    cut_ = cut_ || to_limit;
    return 0;
  }
  const ssize_t n = ::recv(fd_, buffer, count, 0);
  if (n > 0)
  {
    bytes_read_ += static_cast<uint64_t>(n);
    return static_cast<size_t>(n);
  }
  if (n == 0)
    die("the sensor closed the connection");
  else if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
    die(std::string("read failed: ") + std::strerror(errno));
  return 0;
}

size_t TcpStream::Write(const void* buffer, size_t count)
{
  const auto* p = static_cast<const char*>(buffer);
  size_t sent = 0;
  while (!dead_ && sent < count)
  {
    const ssize_t n = ::send(fd_, p + sent, count - sent, MSG_NOSIGNAL);
    if (n > 0)
    {
      sent += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
    {
      pollfd q{fd_, POLLOUT, 0};
      if (::poll(&q, 1, static_cast<int>(read_timeout_.count())) != 1) die("write timed out");
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    die(std::string("write failed: ") + std::strerror(errno));
  }
  return count;  // dropped bytes of a dead link count as written (see the header)
}

}  // namespace swslam::io
