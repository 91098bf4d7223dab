#include <swslam/io/hokuyo_link.h>

#include <swslam/io/tcp_stream.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/CHokuyoURG.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <thread>

namespace swslam::io
{
using namespace std::chrono;

namespace
{
/** Keys CHokuyoURG and MRPT's sensor base classes read (MRPT 2.5). */
const char* const kHokuyoKeys[] = {
    "driver", "sensorLabel", "process_rate", "max_queue_len", "grab_decimation",
    "pose_x", "pose_y", "pose_z", "pose_yaw", "pose_pitch", "pose_roll",
    "COM_port_LIN", "COM_port_WIN", "IP_DIR", "PORT_DIR", "HOKUYO_motorSpeed_rpm",
    "HOKUYO_HS_mode", "disable_firmware_timestamp", "intensity", "scan_interval",
    "reduced_fov", "comms_timeout_ms", "preview", "preview_decimation", "external_images_format",
    "external_images_jpeg_quality", "path_to_external_images"};

bool knownKey(const std::string& key)
{
  if (std::find(std::begin(kHokuyoKeys), std::end(kHokuyoKeys), key) != std::end(kHokuyoKeys)) return true;
  // Exclusion zones and angles are numbered: exclusionZone1_x, exclusionAngles2_ini, ...
  return key.rfind("exclusionZone", 0) == 0 || key.rfind("exclusionAngles", 0) == 0;
}
}  // namespace

void checkHokuyoSection(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
  if (!cfg.sectionExists(section))
    throw std::invalid_argument("sensor config: no section [" + section + "]");
  const std::string driver = mrpt::system::trim(cfg.read_string(section, "driver", ""));
  if (driver != "CHokuyoURG")
    throw std::invalid_argument("sensor config [" + section + "]: driver = '" + driver +
                                "'; swslam-live drives CHokuyoURG");
  std::vector<std::string> keys;
  cfg.getAllKeys(section, keys);
  for (const auto& raw : keys)
  {
    const std::string key = mrpt::system::trim(raw);
    if (!knownKey(key))
      throw std::invalid_argument("sensor config [" + section + "]: unknown key '" + key +
                                  "' (not read by CHokuyoURG)");
  }
  const bool serial = !cfg.read_string(section, "COM_port_LIN", "").empty();
  const bool ethernet = !cfg.read_string(section, "IP_DIR", "").empty();
  if (serial == ethernet)
    throw std::invalid_argument("sensor config [" + section +
                                "]: give either COM_port_LIN (USB/serial) or IP_DIR + PORT_DIR (Ethernet)");
}

HokuyoLink::HokuyoLink(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                       HokuyoLinkOptions options, Log log)
    : section_(section), options_(options), log_(std::move(log)), backoff_(options.min_backoff)
{
  checkHokuyoSection(cfg, section);
  // Kept as text: every reconnection configures a fresh driver from it.
  std::vector<std::string> keys;
  cfg.getAllKeys(section, keys);
  for (const auto& raw : keys)
  {
    const std::string key = mrpt::system::trim(raw);
    const std::string line = key + " = " + cfg.read_string(section, raw, "") + "\n";
    ini_text_ += line;
    if (key != "IP_DIR" && key != "PORT_DIR" && key != "COM_port_LIN" && key != "COM_port_WIN")
      ini_without_link_ += line;
  }
  ip_ = mrpt::system::trim(cfg.read_string(section, "IP_DIR", ""));
  port_ = cfg.read_int(section, "PORT_DIR", 10940);
  serial_ = mrpt::system::trim(cfg.read_string(section, "COM_port_LIN", ""));
  retry_at_ = steady_clock::now();
}

HokuyoLink::~HokuyoLink() { dropDriver(); }

bool HokuyoLink::reachable(std::string& why) const
{
  if (!ip_.empty()) return true;  // connecting the TcpStream is the probe
  const std::string dev = serial_.rfind("/", 0) == 0 ? serial_ : "/dev/" + serial_;
  if (std::filesystem::exists(dev)) return true;
  why = "serial port " + dev + " not present";
  return false;
}

bool HokuyoLink::connect(std::string& why)
{
  std::string ini = ini_text_;
  if (!ip_.empty())
  {
    // Ethernet: our own stream (MRPT's socket can spin on a failed write); the driver is
    // told it talks to a generic stream (a placeholder port name it never opens).
    stream_ = std::make_shared<TcpStream>(ip_, port_, milliseconds(1000), milliseconds(100));
    stream_->setStop(options_.stop);
    ini = ini_without_link_ + "COM_port_LIN = swslam-tcp\n";
  }
  mrpt::config::CConfigFileMemory mem("[" + section_ + "]\n" + ini);
  driver_ = std::make_unique<mrpt::hwdrivers::CHokuyoURG>();
  if (stream_) driver_->bindIO(stream_);
  // The driver's own error messages go to our log, the first few per outage in full.
  driver_->logging_enable_console_output = false;
  driver_->logRegisterCallback([this](std::string_view msg, mrpt::system::VerbosityLevel level,
                                      std::string_view, mrpt::Clock::time_point) {
    if (level < mrpt::system::LVL_ERROR || dropping_ || stopping()) return;
    stats_.driver_messages++;
    last_driver_message_ = mrpt::system::trim(std::string(msg));
    if (driver_messages_this_outage_++ < kMaxDriverMessages) log_("sensor driver: " + last_driver_message_);
  });
  driver_->loadConfig(mem, section_);
  const size_t before = stats_.driver_messages;
  if (stream_) garbage_meter_.connected(0);
  const uint64_t bytes = limitReads(options_.connect_budget);
  static_cast<mrpt::hwdrivers::CGenericSensor&>(*driver_).initialize();  // public in the base
  stats_.connects++;
  last_scan_ = steady_clock::now();
  if (stats_.driver_messages == before)
  {
    if (stream_) garbage_meter_.connected(stream_->bytesRead());
    return true;
  }
  why = garbage(bytes);
  if (why.empty()) why = last_driver_message_;
  // A failed start is not polled (MRPT 2.5 can spin in it): it is replaced.
  dropDriver();
  return false;
}

uint64_t HokuyoLink::limitReads(milliseconds budget)
{
  if (!stream_) return 0;
  stream_->limitReads(steady_clock::now() + budget);
  return stream_->bytesRead();
}

std::string HokuyoLink::garbage(uint64_t bytes_before)
{
  // A call cut to stop may have been reading a good scan: those bytes are not judged.
  if (!stream_ || stopping()) return "";
  const uint64_t read = stream_->bytesRead();
  const bool starts = garbage_meter_.noScan(bytes_before, read, stream_->cut());
  stats_.garbage_bytes = garbage_meter_.bytes();
  if (!starts) return "";
  return "the link sends data that is not SCIP 2.0 (" + std::to_string(garbage_meter_.sinceScan(read)) +
         " bytes without a valid reply or scan: is " + ip_ + ":" + std::to_string(port_) + " a Hokuyo?)";
}

void HokuyoLink::trouble(const std::string& why)
{
  if (!in_outage_)
  {
    log_("sensor: " + why + "; the map is kept, waiting for the sensor");
    in_outage_ = true;
    outage_start_ = steady_clock::now();
  }
  stats_.connected = false;
}

std::string HokuyoLink::address() const { return ip_.empty() ? serial_ : ip_ + ":" + std::to_string(port_); }

std::string HokuyoLink::retryPolicy() const
{
  return "reconnecting after " + std::to_string(options_.min_backoff.count()) + " ms, doubling up to " +
         std::to_string(options_.max_backoff.count()) + " ms, for as long as the run lasts";
}

void HokuyoLink::retryLater(const std::string& why)
{
  trouble(why);
  retry_at_ = steady_clock::now() + backoff_;
  backoff_ = std::min(options_.max_backoff, backoff_ * 2);
}

bool HokuyoLink::connectWhenDue()
{
  const auto now = steady_clock::now();
  if (now < retry_at_)
  {
    std::this_thread::sleep_for(std::min<steady_clock::duration>(retry_at_ - now, milliseconds(100)));
    return false;
  }
  std::string why;
  stats_.attempts++;
  if (!reachable(why))
  {
    retryLater(why + " (retrying, up to every " + std::to_string(options_.max_backoff.count()) + " ms)");
    return false;
  }
  try
  {
    std::string failure;
    if (!connect(failure))
    {
      if (stopping()) return false;  // cut short to stop: not a failure
      stats_.errors++;
      retryLater("initialization failed: " + failure);
      return false;
    }
  }
  catch (const std::exception& e)
  {
    dropDriver();
    stats_.errors++;
    retryLater(std::string("cannot connect: ") + mrpt::system::trim(e.what()).substr(0, 200));
    return false;
  }
  return true;
}

void HokuyoLink::scanReceived()
{
  if (in_outage_)
  {
    const double s = duration<double>(steady_clock::now() - outage_start_).count();
    log_("sensor: receiving scans again after " + std::to_string(static_cast<int>(s * 10) / 10.0).substr(0, 4) + " s");
  }
  else if (stats_.scans == 0)
    log_("sensor: receiving scans");
  in_outage_ = false;
  driver_messages_this_outage_ = 0;
  if (stream_) garbage_meter_.scan(stream_->bytesRead());
  stats_.scans++;
  stats_.connected = true;
  backoff_ = options_.min_backoff;
  last_scan_ = steady_clock::now();
}

mrpt::obs::CObservation2DRangeScan::Ptr HokuyoLink::poll()
{
  if (!driver_ && !connectWhenDue()) return nullptr;
  if (stream_ && stream_->dead())
  {
    stats_.errors++;
    dropDriver();
    retryLater("link lost (" + stream_why_ + ")");
    return nullptr;
  }
  // Once initialized, the same driver is kept: it reconnects a lost link by itself from
  // doProcessSimple(), which then fails at once on every call until the sensor is back.
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
  bool there = false, hw_error = false;
  const uint64_t bytes = limitReads(options_.poll_budget);
  try
  {
    driver_->doProcessSimple(there, *obs, hw_error);
  }
  catch (const std::exception& e)
  {
    // After a pause longer than its own timeout MRPT's driver takes the link for dead and
    // throws on every call: a stall as any other, or the link would never come back.
    stats_.errors++;
    trouble(std::string("driver error: ") + mrpt::system::trim(e.what()).substr(0, 200));
    std::this_thread::sleep_for(milliseconds(50));
    checkStall();
    return nullptr;
  }
  if (there)
  {
    scanReceived();
    return obs;
  }
  if (const std::string junk = garbage(bytes); !junk.empty())
    trouble(junk);  // and a stall once it lasts
  if (hw_error)
  {
    stats_.errors++;
    trouble("the driver reports a hardware/link error");
    std::this_thread::sleep_for(milliseconds(20));  // it may fail at once, on every call
  }
  checkStall();
  return nullptr;
}

void HokuyoLink::checkStall()
{
  if (steady_clock::now() - last_scan_ <= options_.stall_timeout) return;
  // Connected but silent: start over (over Ethernet the driver is ours to replace; over
  // serial the driver reopens the port by itself, so it is kept).
  stats_.stalls++;
  if (stream_)
  {
    dropDriver();
    retryLater("no scan for " + std::to_string(options_.stall_timeout.count()) + " ms (stopped answering?)");
  }
  else
  {
    trouble("no scan for " + std::to_string(options_.stall_timeout.count()) + " ms (stopped answering?)");
    last_scan_ = steady_clock::now();
  }
}

void HokuyoLink::dropDriver()
{
  if (stream_)
  {
    stream_why_ = stream_->dead() ? stream_->why() : "closed by swslam";
    stream_->limitReads(steady_clock::now());  // its shut-down replies are not waited for
  }
  dropping_ = true;  // its shut-down commands fail on the dead link: not news
  driver_.reset();   // ...and cannot hang there
  dropping_ = false;
  stream_.reset();
}

}  // namespace swslam::io
