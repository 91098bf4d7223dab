#pragma once
// Tells when a sensor link carries data that is not the sensor's protocol (a peer sending
// garbage: another device on the port, a corrupt link), from the bytes a driver reads and
// the scans it returns: the bytes since the last scan are garbage once a driver call that
// gave no scan was cut at its time budget while data kept coming, or once more than a
// threshold of them came without a scan. A sensor's own replies without a scan (a start-up
// reply, a scan the driver rejects) stay well below the threshold. Pure bookkeeping over
// stream positions (bytes read since the connection opened).

#include <cstdint>

namespace swslam::io
{
class GarbageMeter
{
 public:
  /** `threshold`: bytes without a scan that are garbage even when no call was cut. */
  explicit GarbageMeter(uint64_t threshold) : threshold_(threshold) {}

  /** A new connection; its bytes up to `position` (the start-up replies) were the sensor's. */
  void connected(uint64_t position);
  /** A scan arrived: the bytes up to `position` were the sensor's. */
  void scan(uint64_t position);
  /** A driver call that gave no scan read from `from` to `to`, and was `cut` at its budget or
   * not. Returns true when this makes the bytes since the last scan garbage (cut while data
   * kept coming, or past the threshold; once per stretch between scans); from then on they
   * are counted. */
  bool noScan(uint64_t from, uint64_t to, bool cut);

  /** Bytes counted as garbage, over every connection. */
  uint64_t bytes() const { return bytes_; }
  /** Bytes of the current stretch without a scan. */
  uint64_t sinceScan(uint64_t position) const { return position - last_scan_; }

 private:
  uint64_t threshold_;
  uint64_t last_scan_ = 0;  ///< stream position of the last scan (or of the connection's start)
  uint64_t counted_ = 0;    ///< stream position up to which garbage is counted
  bool garbage_ = false;    ///< the bytes since the last scan are garbage
  uint64_t bytes_ = 0;
};

}  // namespace swslam::io
