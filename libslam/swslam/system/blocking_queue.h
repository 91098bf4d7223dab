#pragma once
// The input queue a module thread owns: producers push, the owner pops until the queue is
// closed and drained. No polling, no sleeps: waiting is on condition variables. A bounded
// queue makes a fast producer (a rawlog read from disk) wait for its consumer.

#include <condition_variable>
#include <algorithm>
#include <deque>
#include <mutex>
#include <optional>

namespace swslam::system
{
template <typename T>
class BlockingQueue
{
 public:
  /** `capacity` = 0: unbounded; otherwise push() waits while that many items are queued. */
  explicit BlockingQueue(size_t capacity = 0) : capacity_(capacity) {}

  /** Appends an item, waiting for room in a bounded queue; returns false (dropping the
   * item) if the queue is or becomes closed. */
  bool push(T item)
  {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (capacity_ > 0)
        room_.wait(lock, [this] { return closed_ || items_.size() < capacity_; });
      if (closed_) return false;
      items_.push_back(std::move(item));
      peak_ = std::max(peak_, items_.size());
    }
    ready_.notify_one();
    return true;
  }

  /** Waits for the next item; std::nullopt once the queue is closed and empty. */
  std::optional<T> pop()
  {
    std::optional<T> item;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [this] { return closed_ || !items_.empty(); });
      item = takeFront();
    }
    room_.notify_one();
    return item;
  }

  /** The next item if there is one, without waiting. */
  std::optional<T> tryPop()
  {
    std::optional<T> item;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      item = takeFront();
    }
    room_.notify_one();
    return item;
  }

  /** No more pushes; pop() returns what is left, then std::nullopt. */
  void close()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
    room_.notify_all();
  }

  size_t size() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return items_.size();
  }
  /** Largest number of items waiting at once. */
  size_t peakSize() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return peak_;
  }

 private:
  std::optional<T> takeFront()
  {
    std::optional<T> item;
    if (items_.empty()) return item;
    item.emplace(std::move(items_.front()));
    items_.pop_front();
    return item;
  }

  mutable std::mutex mutex_;
  const size_t capacity_;
  std::condition_variable ready_;  // an item arrived or the queue closed
  std::condition_variable room_;   // an item left or the queue closed
  std::deque<T> items_;  // guarded by mutex_
  size_t peak_ = 0;      // guarded by mutex_
  bool closed_ = false;  // guarded by mutex_
};

}  // namespace swslam::system
