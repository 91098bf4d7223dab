#include "scip_protocol.h"

#include "scip_encoding.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>

namespace swslam::scip
{
namespace
{
bool allDigits(const std::string& s)
{
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(c); });
}

Frame status(const std::string& echo, const char* code) { return Frame{echo, code, {}, false}; }
}  // namespace

Protocol::Protocol(SensorInfo info) : info_(std::move(info))
{
  if (info_.amax < info_.amin || info_.afrt < info_.amin || info_.afrt > info_.amax)
    throw std::invalid_argument("SCIP sensor: AMIN <= AFRT <= AMAX does not hold");
  if (info_.ares == 0 || info_.scan_rpm == 0)
    throw std::invalid_argument("SCIP sensor: ARES and SCAN must be positive");
}

void Protocol::reset()
{
  laser_on_ = false;
  high_sensitivity_ = false;
  meas_.reset();
}

std::optional<Frame> Protocol::reply(const std::string& line)
{
  std::string echo = line;
  if (!echo.empty() && echo.back() == '\r') echo.pop_back();
  if (echo.empty()) return std::nullopt;
  // An optional ";string" tag is echoed but not part of the command.
  const std::string cmd = echo.substr(0, echo.find(';'));
  const std::string code = cmd.substr(0, 2);

  if (cmd == "SCIP2.0") return status(echo, "0E");  // already in SCIP 2.0 mode
  if (cmd == "QT" || cmd == "RS")
  {
    laser_on_ = false;
    meas_.reset();
    if (cmd == "RS") high_sensitivity_ = false;
    return status(echo, "00");
  }
  if (cmd == "BM")
  {
    const bool was_on = laser_on_;
    laser_on_ = true;
    return status(echo, was_on ? "02" : "00");
  }
  if (code == "HS")
  {
    if (cmd != "HS0" && cmd != "HS1") return status(echo, "01");
    const bool on = cmd == "HS1";
    const bool same = on == high_sensitivity_;
    high_sensitivity_ = on;
    return status(echo, same ? "02" : "00");
  }
  if (code == "CR")
  {
    const std::string arg = cmd.substr(2);
    const bool ok = arg.size() == 2 && allDigits(arg) && (std::stoi(arg) <= 10 || arg == "99");
    return status(echo, ok ? "00" : "01");
  }
  if (cmd == "PP")
  {
    Frame f = status(echo, "00");
    f.info_lines = true;
    f.lines = {"MODL:" + info_.model,
               "DMIN:" + std::to_string(info_.dmin),
               "DMAX:" + std::to_string(info_.dmax),
               "ARES:" + std::to_string(info_.ares),
               "AMIN:" + std::to_string(info_.amin),
               "AMAX:" + std::to_string(info_.amax),
               "AFRT:" + std::to_string(info_.afrt),
               "SCAN:" + std::to_string(info_.scan_rpm)};
    return f;
  }
  if (cmd == "VV")
  {
    Frame f = status(echo, "00");
    f.info_lines = true;
    f.lines = {"VEND:swslam test suite", "PROD:SCIP 2.0 emulator of a " + info_.model,
               "FIRM:1.0.0", "PROT:SCIP 2.0", "SERI:" + info_.serial};
    return f;
  }
  if (code == "MD" || code == "ME") return measure(echo);
  return status(echo, "0E");  // undefined command
}

Frame Protocol::measure(const std::string& echo)
{
  const std::string cmd = echo.substr(0, echo.find(';'));
  // MD/ME, start step (4), end step (4), cluster (2), scan interval (1), scans (2).
  if (cmd.size() != 15) return status(echo, "0C");
  const std::string start = cmd.substr(2, 4), end = cmd.substr(6, 4), cluster = cmd.substr(10, 2),
                    skip = cmd.substr(12, 1), count = cmd.substr(13, 2);
  if (!allDigits(start)) return status(echo, "01");
  if (!allDigits(end)) return status(echo, "02");
  if (!allDigits(cluster)) return status(echo, "03");
  Measurement m;
  m.command = echo;
  m.intensity = cmd[1] == 'E';
  m.start = static_cast<uint32_t>(std::stoul(start));
  m.end = static_cast<uint32_t>(std::stoul(end));
  if (m.start < info_.amin || m.end > info_.amax) return status(echo, "04");
  if (m.end < m.start) return status(echo, "05");
  if (!allDigits(skip)) return status(echo, "06");
  if (!allDigits(count)) return status(echo, "07");
  m.cluster = std::max<uint32_t>(1, static_cast<uint32_t>(std::stoul(cluster)));
  m.skip = static_cast<uint32_t>(std::stoul(skip));
  m.remaining = static_cast<uint32_t>(std::stoul(count));
  m.endless = m.remaining == 0;
  laser_on_ = true;
  meas_ = m;
  period_ = 0;
  return status(echo, "00");
}

bool Protocol::scanDue()
{
  if (!meas_) return false;
  return period_++ % (meas_->skip + 1) == 0;
}

std::string Protocol::echoOf(const Measurement& m) const
{
  // Scans echo the command with the number of scans still to come after this one.
  std::string echo = m.command;
  if (!m.endless)
  {
    char left[3];
    std::snprintf(left, sizeof left, "%02u", m.remaining - 1);
    echo.replace(13, 2, left);
  }
  return echo;
}

Frame Protocol::scanFrame(const Scan& scan, uint32_t timestamp_ms)
{
  if (!meas_) throw std::logic_error("SCIP scan frame without a measurement request");
  const Measurement& m = *meas_;
  if (scan.ranges_mm.size() != info_.steps())
    throw std::invalid_argument("SCIP scan: " + std::to_string(scan.ranges_mm.size()) +
                                " ranges, the sensor has " + std::to_string(info_.steps()) +
                                " steps");
  if (m.intensity && !scan.intensities.empty() && scan.intensities.size() != info_.steps())
    throw std::invalid_argument("SCIP scan: " + std::to_string(scan.intensities.size()) +
                                " intensities for " + std::to_string(info_.steps()) + " steps");

  std::string data;
  for (uint32_t first = m.start; first <= m.end; first += m.cluster)
  {
    // A cluster of steps reports its smallest range (and that step's intensity).
    const uint32_t last = std::min(m.end, first + m.cluster - 1);
    size_t best = first - info_.amin;
    for (uint32_t s = first; s <= last; s++)
      if (scan.ranges_mm[s - info_.amin] < scan.ranges_mm[best]) best = s - info_.amin;
    data += encode(scan.ranges_mm[best], 3);
    if (m.intensity) data += encode(scan.intensities.empty() ? 0 : scan.intensities[best], 3);
  }
  Frame f{echoOf(m), "99", {encode(timestamp_ms % kTimestampModulo, 4)}, false};
  for (auto& block : splitBlocks(data)) f.lines.push_back(std::move(block));

  if (!m.endless && --meas_->remaining == 0)
  {
    meas_.reset();  // the last scan of a finite request; the laser stays on
  }
  return f;
}

}  // namespace swslam::scip
