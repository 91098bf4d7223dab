#include <swslam/io/sandboxed_decoder.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <new>
#include <poll.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace swslam::io
{
/** The page the parent and the child share: where the child is, and whether it went over its
 * memory budget. */
struct SandboxedDecoder::Shared
{
  std::atomic<uint64_t> index{0};
  std::atomic<uint64_t> offset{0};
  std::atomic<uint64_t> steps{0};  ///< marks and frames so far: the child's progress
  std::atomic<int> out_of_memory{0};
};

namespace
{
enum class FrameKind : uint8_t
{
  Data = 1,
  End = 2,
  Error = 3,
};

/** A frame's header, as sent over the pipe (both ends are the same program). */
struct FrameHeader
{
  uint8_t kind;
  uint64_t index;
  uint64_t offset;
  double fraction;
  uint64_t length;
};

/** The pipe's buffer, if the system allows it (/proc/sys/fs/pipe-max-size, 1 MB by default). */
constexpr int kPipeBytes = 1 << 20;

/** An error's message is cut to this (MRPT's carry call stacks). */
constexpr size_t kMaxErrorMessage = 4096;

/** Address space left beyond the budget under AddressSanitizer: an allocation the limit
 * refuses is a sanitizer report there, which needs memory of its own to be written (its
 * resident memory holds the child to the budget itself). */
constexpr uint64_t kSanitizerReportReserve = uint64_t(512) << 20;

// AddressSanitizer's, when the program runs under it (null otherwise).
extern "C" void __asan_set_error_report_callback(void (*callback)(const char*)) __attribute__((weak));

/** The exit status of a child stopped over its budget (the shared page says why). */
constexpr int kOverBudgetExit = 9;

// The child's only, set before its work runs.
std::atomic<int>* g_out_of_memory = nullptr;
uint64_t g_page_bytes = 4096;
uint64_t g_resident_limit = 0;  ///< its resident size at the start plus the budget

void onOutOfMemory()
{
  if (g_out_of_memory) g_out_of_memory->store(1);
  throw std::bad_alloc();
}

/** Field `field` of /proc/self/statm in bytes (0: the address-space size, which RLIMIT_AS
 * limits; 1: the resident size), 0 if unknown. Async-signal-safe: no allocation, no stdio. */
uint64_t statmBytes(int field)
{
  char text[160];
  const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  const ssize_t n = ::read(fd, text, sizeof(text));
  ::close(fd);
  ssize_t k = 0;
  for (int skip = 0; skip < field; skip++)
  {
    while (k < n && text[k] != ' ') k++;
    k++;
  }
  uint64_t pages = 0;
  for (; k < n && text[k] >= '0' && text[k] <= '9'; k++) pages = 10 * pages + static_cast<uint64_t>(text[k] - '0');
  return pages * g_page_bytes;
}

/** The watch of the child's resident memory, every kResidentWatchPeriod of its CPU time
 * (SIGPROF): memory the address-space limit does not see (AddressSanitizer's allocator maps its
 * space in advance; pages mapped before the fork) is still within the budget. */
void onWatchTick(int)
{
  const int interrupted_errno = errno;  // the interrupted code's, whatever it was doing
  if (statmBytes(1) > g_resident_limit)
  {
    g_out_of_memory->store(1);
    _exit(kOverBudgetExit);
  }
  errno = interrupted_errno;
}

/** Under AddressSanitizer an allocation the address-space limit refuses is a fatal report, not
 * std::bad_alloc: that report is the budget's failure too (any other report goes on to end
 * the child as a crash). */
void onSanitizerReport(const char* report)
{
  for (const char* oom : {"AddressSanitizer: out of memory", "AddressSanitizer: out-of-memory",
                          "AddressSanitizer: requested allocation size", "AddressSanitizer: allocation-size-too-big"})
  {
    if (!std::strstr(report, oom)) continue;
    g_out_of_memory->store(1);
    _exit(kOverBudgetExit);
  }
}

bool writeFully(int fd, const char* buf, size_t len)
{
  while (len > 0)
  {
    const ssize_t w = ::write(fd, buf, len);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    buf += w;
    len -= static_cast<size_t>(w);
  }
  return true;
}

/** The child's side of the pipe. */
class PipeChannel : public DecodeChannel
{
 public:
  PipeChannel(int fd, std::atomic<uint64_t>& index, std::atomic<uint64_t>& offset, std::atomic<uint64_t>& steps)
      : fd_(fd), index_(index), offset_(offset), steps_(steps)
  {
  }
  void mark(DecodePosition at) override
  {
    at_ = at;
    index_.store(at.index);
    offset_.store(at.offset);
    steps_++;
  }
  void send(double fraction, const std::string& payload) override { frame(FrameKind::Data, fraction, payload); }
  void frame(FrameKind kind, double fraction, const std::string& payload)
  {
    FrameHeader h;
    std::memset(&h, 0, sizeof(h));  // no uninitialized padding down the pipe
    h = {static_cast<uint8_t>(kind), at_.index, at_.offset, fraction, payload.size()};
    buffer_.assign(reinterpret_cast<const char*>(&h), sizeof(h));
    buffer_ += payload;
    steps_++;
    // The parent stopped reading (it closed the pipe, or died): nothing left to do.
    if (!writeFully(fd_, buffer_.data(), buffer_.size())) _exit(3);
  }

 private:
  int fd_;
  std::atomic<uint64_t>& index_;
  std::atomic<uint64_t>& offset_;
  std::atomic<uint64_t>& steps_;
  DecodePosition at_;
  std::string buffer_;
};

/** Sets the child apart from the parent: default crash signals (no core file), the terminal's
 * interrupt left to the parent, a closed pipe an error rather than a signal, no descriptor of
 * the parent's but the pipe and the standard ones (stdout goes to stderr: the parent's output
 * is its own), and the memory budget: the address-space limit first, then the watch of its
 * resident memory. */
void isolateChild(int fd, uint64_t memory_budget, std::atomic<int>& out_of_memory)
{
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTERM}) std::signal(sig, SIG_DFL);
  std::signal(SIGINT, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (fd > 3) close_range(3, static_cast<unsigned>(fd) - 1, 0);
  close_range(static_cast<unsigned>(fd) + 1, ~0u, 0);
  dup2(STDERR_FILENO, STDOUT_FILENO);
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  rlimit as{};
  getrlimit(RLIMIT_AS, &as);
  g_page_bytes = static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
  const bool sanitized = __asan_set_error_report_callback != nullptr;
  const uint64_t limit = statmBytes(0) + memory_budget + (sanitized ? kSanitizerReportReserve : 0);
  if (as.rlim_max == RLIM_INFINITY || limit < as.rlim_max) as.rlim_cur = limit;
  setrlimit(RLIMIT_AS, &as);

  g_out_of_memory = &out_of_memory;
  std::set_new_handler(onOutOfMemory);
  if (sanitized) __asan_set_error_report_callback(onSanitizerReport);
  g_resident_limit = statmBytes(1) + memory_budget;
  struct sigaction watch{};
  watch.sa_handler = onWatchTick;
  watch.sa_flags = SA_RESTART;
  sigemptyset(&watch.sa_mask);
  sigaction(SIGPROF, &watch, nullptr);
  constexpr suseconds_t kPeriod = std::chrono::microseconds(kResidentWatchPeriod).count();
  const itimerval every{{0, kPeriod}, {0, kPeriod}};
  setitimer(ITIMER_PROF, &every, nullptr);
}

[[noreturn]] void runChild(const SandboxedDecoder::Work& work, int fd, std::atomic<uint64_t>& index,
                           std::atomic<uint64_t>& offset, std::atomic<uint64_t>& steps,
                           std::atomic<int>& out_of_memory, uint64_t memory_budget)
{
  isolateChild(fd, memory_budget, out_of_memory);
  PipeChannel channel(fd, index, offset, steps);
  int code = 0;
  try
  {
    work(channel);
    channel.frame(FrameKind::End, 1.0, "");
  }
  catch (const std::exception& e)
  {
    channel.frame(FrameKind::Error, 0, std::string(e.what()).substr(0, kMaxErrorMessage));
    code = 1;
  }
  catch (...)
  {
    channel.frame(FrameKind::Error, 0, "an unknown exception");
    code = 1;
  }
  // Never the parent's atexit handlers, static destructors or stdio buffers.
  _exit(code);
}

std::string overBudget(uint64_t budget)
{
  return "decoding it needed more than " + formatBytes(budget) + " of memory (the decoder's budget)";
}

std::string signalName(int sig)
{
  const char* abbrev = sigabbrev_np(sig);
  return abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(sig);
}
}  // namespace

std::string formatBytes(uint64_t bytes)
{
  constexpr uint64_t kMB = uint64_t(1) << 20, kGB = uint64_t(1) << 30;
  if (bytes >= kGB && bytes % kGB == 0) return std::to_string(bytes / kGB) + " GB";
  if (bytes >= kMB) return std::to_string(bytes / kMB) + " MB";
  return std::to_string(bytes) + " bytes";
}

SandboxedDecoder::SandboxedDecoder(Work work, uint64_t memory_budget, std::chrono::milliseconds stall_timeout)
    : memory_budget_(memory_budget), stall_timeout_(stall_timeout)
{
  void* page = mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (page == MAP_FAILED) throw std::runtime_error(std::string("decoder: cannot map its shared page: ") + std::strerror(errno));
  shared_ = new (page) Shared;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0)
  {
    munmap(shared_, sizeof(Shared));
    throw std::runtime_error(std::string("decoder: cannot make its pipe: ") + std::strerror(errno));
  }
  // Room for the child to run ahead by a hundred scans rather than a few (the default 64 kB):
  // fewer hand-overs between the two processes. Not an error if the system allows less.
  fcntl(fds[0], F_SETPIPE_SZ, kPipeBytes);
  std::fflush(nullptr);  // else the child's copy of unwritten output could be written twice
  const pid_t pid = fork();
  if (pid == 0)
  {
    ::close(fds[0]);
    runChild(work, fds[1], shared_->index, shared_->offset, shared_->steps, shared_->out_of_memory, memory_budget);
  }
  const int fork_errno = errno;
  ::close(fds[1]);
  if (pid < 0)
  {
    ::close(fds[0]);
    munmap(shared_, sizeof(Shared));
    throw std::runtime_error(std::string("decoder: cannot start its process: ") + std::strerror(fork_errno));
  }
  fd_ = fds[0];
  pid_ = pid;
}

SandboxedDecoder::~SandboxedDecoder()
{
  if (pid_ > 0) reap(true);
  if (fd_ >= 0) ::close(fd_);
  munmap(shared_, sizeof(Shared));
}

int SandboxedDecoder::reap(bool kill_first)
{
  if (pid_ <= 0) return 0;
  if (!kill_first)
  {
    // The pipe has ended: the child is exiting. Give it a moment, not forever.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline)
    {
      const pid_t r = waitpid(pid_, &status, WNOHANG);
      if (r == pid_ || (r < 0 && errno != EINTR))
      {
        pid_ = -1;
        return status;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  kill(pid_, SIGKILL);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR)
  {
  }
  pid_ = -1;
  return status;
}

DecodeFailure SandboxedDecoder::deathFailure()
{
  const int status = reap(false);
  const DecodePosition at{shared_->index.load(), shared_->offset.load()};
  std::string what;
  if (shared_->out_of_memory.load())
    what = overBudget(memory_budget_);
  else if (WIFSIGNALED(status))
    what = "the decoder crashed with " + signalName(WTERMSIG(status));
  else if (WIFEXITED(status))
    what = "the decoder stopped (exit status " + std::to_string(WEXITSTATUS(status)) + ") before the end";
  else
    what = "the decoder stopped before the end";
  return DecodeFailure(what, at);
}

DecodeFailure SandboxedDecoder::failed(DecodeFailure f)
{
  reap(true);
  failure_ = f.what();
  failed_at_ = f.at();
  return f;
}

size_t SandboxedDecoder::receive(void* buf, size_t len)
{
  size_t got = 0;
  uint64_t steps = shared_->steps.load();
  auto waited = std::chrono::milliseconds(0);
  constexpr auto kPollPeriod = std::chrono::milliseconds(100);
  while (got < len)
  {
    pollfd p{fd_, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min(kPollPeriod, stall_timeout_).count()));
    if (ready == 0)
    {
      // Nothing to read: fine while the child moves on (entries that give no frame).
      const uint64_t now = shared_->steps.load();
      waited = now == steps ? waited + std::min(kPollPeriod, stall_timeout_) : std::chrono::milliseconds(0);
      steps = now;
      if (waited < stall_timeout_) continue;
      throw failed(DecodeFailure("the decoder made no progress for " + std::to_string(stall_timeout_.count()) +
                                     " ms on this entry (stuck: stopped)",
                                 {shared_->index.load(), shared_->offset.load()}));
    }
    if (ready < 0 && errno == EINTR) continue;
    const ssize_t r = ::read(fd_, static_cast<char*>(buf) + got, len - got);
    if (r > 0)
    {
      got += static_cast<size_t>(r);
      waited = std::chrono::milliseconds(0);
    }
    else if (r == 0 || errno != EINTR)
      break;
  }
  return got;
}

bool SandboxedDecoder::next(DecodedFrame& frame)
{
  if (!failure_.empty()) throw DecodeFailure(failure_, failed_at_);
  if (ended_) return false;
  FrameHeader h{};
  if (receive(&h, sizeof(h)) < sizeof(h)) throw failed(deathFailure());
  frame.at = {h.index, h.offset};
  frame.fraction = h.fraction;
  if (h.length > kMaxDecodedFrameBytes)
    throw failed(DecodeFailure("the decoder sent a frame of " + std::to_string(h.length) + " bytes (more than " +
                                 formatBytes(kMaxDecodedFrameBytes) + ")",
                             frame.at));
  frame.payload.resize(h.length);
  if (receive(frame.payload.data(), h.length) < h.length) throw failed(deathFailure());
  switch (static_cast<FrameKind>(h.kind))
  {
    case FrameKind::Data:
      return true;
    case FrameKind::End:
      ended_ = true;
      reap(false);
      return false;
    case FrameKind::Error:
      throw failed(DecodeFailure(shared_->out_of_memory.load() ? overBudget(memory_budget_) : frame.payload, frame.at));
  }
  throw failed(DecodeFailure("the decoder sent a frame of unknown kind " + std::to_string(h.kind), frame.at));
}

}  // namespace swslam::io
