#pragma once
// Messages about input scans that feed() skipped or took in part, for a program's error stream:
// the first few of each kind are printed, every one is counted ([system] max_printed_warnings).

#include <swslam/system/slam_system.h>

#include <cstddef>
#include <map>
#include <ostream>
#include <string>

namespace swslam::app
{
class SkipReporter
{
 public:
  /** Each printed line starts with `prefix` (e.g. "swslam: "). */
  SkipReporter(std::ostream& err, int max_printed, std::string prefix);

  /** One scan's message (FeedResult::message); `input_index` counts the input's scans from 0. */
  void report(system::FeedStatus kind, size_t input_index, const std::string& why);

  /** Messages of this kind so far, printed or not. */
  size_t count(system::FeedStatus kind) const;

 private:
  std::ostream& err_;
  size_t max_;
  std::string prefix_;
  std::map<system::FeedStatus, size_t> counts_;
};
}  // namespace swslam::app
