#pragma once
// SIGINT/SIGTERM as a request to stop: while a StopSignal exists, the first signal sets a
// flag the run loop checks (so it can finish the threads and write every output); a second
// one ends the process the default way.

#include <atomic>

namespace swslam::app
{
class StopSignal
{
 public:
  StopSignal();   ///< installs the handlers
  ~StopSignal();  ///< restores the previous ones
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  bool requested() const;
  /** The signal number received, 0 if none. */
  int signal() const;
};

}  // namespace swslam::app
