#include <swslam/io/throttled_scan_source.h>

#include <stdexcept>

namespace swslam::io
{
ThrottledScanSource::ThrottledScanSource(std::unique_ptr<ScanSource> source, size_t every)
    : source_(std::move(source)), every_(every)
{
  if (!source_) throw std::invalid_argument("ThrottledScanSource: no source");
  if (every_ == 0) throw std::invalid_argument("every Nth scan: N must be at least 1");
}

bool ThrottledScanSource::next(sensor::ScanInput& out)
{
  // The motion since the last scan kept; it starts known (the first scan's own increment, if
  // any, is its motion) and becomes unknown with any scan that has none.
  std::optional<mrpt::poses::CPose2D> motion = mrpt::poses::CPose2D();
  sensor::ScanInput in;
  while (source_->next(in))
  {
    const bool keep = read_++ % every_ == 0;
    if (motion && in.odometry_increment)
      motion = *motion + *in.odometry_increment;
    else
      motion.reset();
    if (!keep)
    {
      left_out_++;
      continue;
    }
    in.odometry_increment = motion;
    out = std::move(in);
    return true;
  }
  return false;
}

const ScanSourceStats& ThrottledScanSource::stats() const
{
  stats_ = source_->stats();
  stats_.scans -= std::min(stats_.scans, left_out_);
  return stats_;
}

std::string ThrottledScanSource::describe() const
{
  return source_->describe() + ", one scan in " + std::to_string(every_);
}

std::unique_ptr<ScanSource> throttleScans(std::unique_ptr<ScanSource> source, size_t every)
{
  if (every == 1) return source;
  return std::make_unique<ThrottledScanSource>(std::move(source), every);
}

}  // namespace swslam::io
