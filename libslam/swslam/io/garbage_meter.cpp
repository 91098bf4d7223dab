#include <swslam/io/garbage_meter.h>

#include <algorithm>

namespace swslam::io
{
void GarbageMeter::connected(uint64_t position)
{
  last_scan_ = counted_ = position;
  garbage_ = false;
}

void GarbageMeter::scan(uint64_t position) { connected(position); }

bool GarbageMeter::noScan(uint64_t from, uint64_t to, bool cut)
{
  const uint64_t position = std::max(to, counted_);  // positions only grow on one connection
  const bool starts = !garbage_ && ((cut && to > from) || position - last_scan_ > threshold_);
  if (starts) garbage_ = true;
  if (garbage_)
  {
    bytes_ += position - counted_;
    counted_ = position;
  }
  return starts;
}

}  // namespace swslam::io
