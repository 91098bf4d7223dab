#include <swslam/app/stop_signal.h>

#include <atomic>
#include <csignal>

namespace swslam::app
{
namespace
{
// The handler runs on whichever thread the kernel picks (the module threads do not block the
// signals) and the run loop reads the flag on another: a volatile sig_atomic_t is only safe
// within one thread, a lock-free atomic is safe across threads and in a signal handler.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal flag must be lock-free");
struct sigaction g_old_int, g_old_term;

extern "C" void onStopSignal(int sig)
{
  g_signal = sig;
  // A second signal: the default action.
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}
}  // namespace

StopSignal::StopSignal()
{
  g_signal = 0;
  struct sigaction sa = {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
}

StopSignal::~StopSignal()
{
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
}

bool StopSignal::requested() const { return g_signal != 0; }
int StopSignal::signal() const { return g_signal; }

}  // namespace swslam::app
