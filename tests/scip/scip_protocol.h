#pragma once
// The command side of an emulated SCIP 2.0 sensor, without sockets: it answers one
// command line at a time (QT, RS, SCIP2.0, BM, HS, CR, PP, VV, MD, ME; anything else gets
// status "0E") and builds the frames of the scans an MD/ME request streams.

#include "scip_frame.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swslam::scip
{
/** What the sensor reports in PP and VV. Defaults: a Hokuyo UTM-30LX (steps 0..1080 of
 * 1440 per turn, front at 540: 270 deg; 23 mm to 60 m; 2400 rpm = 40 scans/s). */
struct SensorInfo
{
  std::string model = "UTM-30LX";
  uint32_t dmin = 23, dmax = 60000;   ///< [mm]
  uint32_t ares = 1440;               ///< steps per turn
  uint32_t amin = 0, amax = 1080, afrt = 540;
  uint32_t scan_rpm = 2400;           ///< scans per minute
  std::string serial = "H0000001";

  uint32_t steps() const { return amax - amin + 1; }
  double scanRate() const { return scan_rpm / 60.0; }  ///< [Hz]
};

/** One scan of the sensor: a range per step amin..amax in mm (values below 20 are SCIP
 * error codes, e.g. kNoEcho), and optionally an intensity per step (ME; 0 if absent). */
struct Scan
{
  std::vector<uint32_t> ranges_mm;
  std::vector<uint32_t> intensities;
};

/** The code sent for a ray without return (below DMIN, so clients discard it). */
constexpr uint32_t kNoEcho = 1;

/** An MD/ME request being served. */
struct Measurement
{
  std::string command;  ///< as received, without LF
  bool intensity = false;
  uint32_t start = 0, end = 0, cluster = 1, skip = 0;
  uint32_t remaining = 0;  ///< scans still to send (0: endless)
  bool endless = true;
};

class Protocol
{
 public:
  explicit Protocol(SensorInfo info = {});

  /** The reply to `command` (one line, without LF; a trailing CR is ignored). Empty lines
   * get no reply (nothing returned). */
  std::optional<Frame> reply(const std::string& command);

  /** The request being streamed, if any. */
  const std::optional<Measurement>& measurement() const { return meas_; }

  /** Called once per scan period while measuring: whether this period's scan is sent
   * (the request's scan interval skips the others). */
  bool scanDue();

  /** The frame of `scan` for the current request, stamped `timestamp_ms` (mod 2^24).
   * Counts the request down; the last of a finite request ends it. Throws
   * std::invalid_argument if `scan` does not have one range per step (and, with
   * intensities, one intensity per step). */
  Frame scanFrame(const Scan& scan, uint32_t timestamp_ms);

  /** The power-on state (laser off, no request), e.g. for a new connection. */
  void reset();

  bool laserOn() const { return laser_on_; }
  const SensorInfo& info() const { return info_; }

 private:
  SensorInfo info_;
  bool laser_on_ = false;
  bool high_sensitivity_ = false;
  std::optional<Measurement> meas_;
  uint32_t period_ = 0;  ///< scan periods since the request started

  Frame measure(const std::string& command);
  std::string echoOf(const Measurement& m) const;
};

}  // namespace swslam::scip
