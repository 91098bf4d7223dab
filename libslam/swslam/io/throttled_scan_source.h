#pragma once
// Every Nth scan of another source (slam_toolbox's throttle_scans): for a sensor faster than
// the motion needs, or to replay a log as a slower sensor would have recorded it. The scans
// left out still count for odometry: the scan kept carries the motion since the last scan
// kept.

#include <swslam/io/scan_source.h>

#include <memory>

namespace swslam::io
{
class ThrottledScanSource : public ScanSource
{
 public:
  /** Keeps the first scan of `source` and then every `every`th one (every >= 1; 1 keeps all). */
  ThrottledScanSource(std::unique_ptr<ScanSource> source, size_t every);

  /** The next scan kept. Its odometry increment composes those of the scans left out since
   * the previous one kept and its own; none if any of them had none. */
  bool next(sensor::ScanInput& out) override;
  /** The inner source's counts, with `scans` the scans returned here. */
  const ScanSourceStats& stats() const override;
  std::string describe() const override;
  double fractionRead() const override { return source_->fractionRead(); }
  std::string noScanReason(const std::string& sensor_label) const override
  {
    return source_->noScanReason(sensor_label);
  }
  /** Scans read from the inner source and left out. */
  size_t leftOut() const { return left_out_; }

 private:
  std::unique_ptr<ScanSource> source_;
  size_t every_;
  size_t read_ = 0, left_out_ = 0;
  mutable ScanSourceStats stats_;
};

/** Wraps `source` in a ThrottledScanSource when every > 1; returns it as is for 1. Throws
 * std::invalid_argument for 0. */
std::unique_ptr<ScanSource> throttleScans(std::unique_ptr<ScanSource> source, size_t every);

}  // namespace swslam::io
