#include <swslam/tracking/prepared_scan.h>

#include <swslam/correlative/score_grid.h>

namespace swslam::tracking
{
PreparedScan::PreparedScan(sensor::Scan scan, const ScanForms& forms)
    : scan_(std::move(scan)), forms_(forms), rotation_length_(sensor::rotationLength(scan_.points))
{
}

const std::shared_ptr<const plicp::ReferenceScan>& PreparedScan::reference() const
{
  if (!reference_) reference_ = std::make_shared<const plicp::ReferenceScan>(scan_, forms_.plicp);
  return reference_;
}

const std::shared_ptr<const FacingNormals>& PreparedScan::facing() const
{
  if (!facing_)
    facing_ = std::make_shared<const FacingNormals>(facingNormals(scan_.points, forms_.plicp.min_segment_length));
  return facing_;
}

const std::vector<Eigen::Vector2d>& PreparedScan::searchPoints() const
{
  if (!search_points_)
    search_points_ = correlative::thinPoints(scan_.points, forms_.search_resolution, forms_.search_max_range);
  return *search_points_;
}

}  // namespace swslam::tracking
