#include <swslam/system/full_optimization_schedule.h>

#include <swslam/geometry/pose_threshold.h>

#include <stdexcept>

namespace swslam::system
{
bool loopCorrectsGraph(const mrpt::poses::CPose2D& graph_relative,
                       const mrpt::poses::CPose2D& measured, double xy, double theta)
{
  return (xy <= 0 && theta <= 0) || geometry::movedBeyond(graph_relative, measured, geometry::MoveThreshold{xy, theta});
}

FullOptimizationSchedule::FullOptimizationSchedule(size_t interval) : interval_(interval)
{
  if (interval == 0)
    throw std::invalid_argument("full optimization schedule: the interval must be >= 1 node");
}

bool FullOptimizationSchedule::fullNow(size_t id, size_t correcting_loops)
{
  if (correcting_loops > 0) pending_ = true;
  if (!pending_ || (last_full_ && id < *last_full_ + interval_)) return false;
  ranFull(id);
  return true;
}

void FullOptimizationSchedule::ranFull(size_t id)
{
  pending_ = false;
  last_full_ = id;
}

}  // namespace swslam::system
