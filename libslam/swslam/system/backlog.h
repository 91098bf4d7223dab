#pragma once
// Work handed from one thread to another and not finished yet, as a count the producer can
// wait on: tracking waits until the graph thread has caught up with the keyframes it sent
// (`[system] max_graph_lag`), so that it goes on from optimized keyframe poses.

#include <condition_variable>
#include <cstddef>
#include <mutex>

namespace swslam::system
{
class Backlog
{
 public:
  /** One more item handed over (producer). */
  void added()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_++;
  }

  /** One item finished (consumer). */
  void done()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (pending_ > 0) pending_--;
    }
    changed_.notify_all();
  }

  /** Waits until at most `n` items are unfinished; false (at once) once closed. */
  bool waitAtMost(size_t n)
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return closed_ || pending_ <= n; });
    return !closed_;
  }

  /** The consumer stopped: waits end, now and later. */
  void close()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closed_ = true;
    }
    changed_.notify_all();
  }

  size_t pending() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return pending_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  size_t pending_ = 0;
  bool closed_ = false;
};

}  // namespace swslam::system
