#include <swslam/map/stored_scan.h>

namespace swslam::map
{
StoredScan::StoredScan(const mrpt::obs::CObservation2DRangeScan& scan)
{
  // resizeScan(0) keeps the vectors' memory; a copy of the emptied scan holds none.
  mrpt::obs::CObservation2DRangeScan header = scan;
  header.resizeScan(0);
  header.setScanHasIntensity(false);
  header_ = header;

  const size_t n = scan.getScanSize();
  ranges_.reserve(n);
  valid_.reserve(n);
  for (size_t i = 0; i < n; i++)
  {
    ranges_.push_back(scan.getScanRange(i));
    valid_.push_back(scan.getScanRangeValidity(i));
  }
}

mrpt::obs::CObservation2DRangeScan StoredScan::restore() const
{
  mrpt::obs::CObservation2DRangeScan scan = header_;
  const size_t n = ranges_.size();
  scan.resizeScan(n);
  for (size_t i = 0; i < n; i++)
  {
    scan.setScanRange(i, ranges_[i]);
    scan.setScanRangeValidity(i, valid_[i]);
  }
  return scan;
}

size_t StoredScan::bytes() const
{
  return sizeof(StoredScan) + ranges_.capacity() * sizeof(float) + (valid_.capacity() + 7) / 8;
}

}  // namespace swslam::map
