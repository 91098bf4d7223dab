#include <swslam/app/skip_reporter.h>

#include <algorithm>

namespace swslam::app
{
SkipReporter::SkipReporter(std::ostream& err, int max_printed, std::string prefix)
    : err_(err), max_(static_cast<size_t>(std::max(max_printed, 0))), prefix_(std::move(prefix))
{
}

void SkipReporter::report(system::FeedStatus kind, size_t input_index, const std::string& why)
{
  const size_t n = ++counts_[kind];
  const char* what = system::scanTaken(kind) ? "input scan " : "skipped input scan ";
  if (n <= max_) err_ << prefix_ << what << input_index << ": " << why << "\n";
  if (n == max_ + 1) err_ << prefix_ << "(further messages of this kind are only counted)\n";
}

size_t SkipReporter::count(system::FeedStatus kind) const
{
  const auto it = counts_.find(kind);
  return it == counts_.end() ? 0 : it->second;
}
}  // namespace swslam::app
