#include <swslam/app/run_record.h>

#include <swslam/common/ini_file.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <stdexcept>

namespace swslam::app
{
namespace
{
constexpr const char* kSection = "run";

std::string required(const mrpt::config::CConfigFileBase& cfg, const std::string& key, const std::string& path)
{
  const std::string v = cfg.read_string(kSection, key, "");
  if (v.empty()) throw std::invalid_argument("run record '" + path + "': [run] " + key + " is missing");
  return v;
}

bool flag(const mrpt::config::CConfigFileBase& cfg, const std::string& key, const std::string& path)
{
  const std::string v = required(cfg, key, path);
  if (v == "true") return true;
  if (v == "false") return false;
  throw std::invalid_argument("run record '" + path + "': [run] " + key + " must be true or false, got '" + v + "'");
}

}  // namespace

std::string RunRecord::swslamVersion() { return SWSLAM_VERSION; }

std::string runRecordText(const RunRecord& r)
{
  mrpt::config::CConfigFileMemory cfg;
  cfg.write(kSection, "program", r.program);
  cfg.write(kSection, "version", r.version);
  cfg.write(kSection, "input", r.input);
  cfg.write(kSection, "odometry", r.use_odometry ? "true" : "false");
  cfg.write(kSection, "deterministic", r.deterministic ? "true" : "false");
  cfg.write(kSection, "sensor_label", r.sensor_label);
  cfg.write(kSection, "scan_topic", r.scan_topic);
  cfg.write(kSection, "odom_topic", r.odom_topic);
  cfg.write(kSection, "max_scans", std::to_string(r.max_scans));
  cfg.write(kSection, "throttle_scans", std::to_string(r.throttle_scans));
  Config::forEachSection(r.config, [&](const auto& table, const auto& p) { table.save(p, cfg); });
  std::string body;
  cfg.getContent(body);
  return "# How this run was made (doc/system.md, Outputs): its program, input and options, every\n"
         "# configuration key it used. swslam -c takes this file as a configuration.\n" +
         body;
}

RunRecord readRunRecord(const std::string& path)
{
  std::unique_ptr<mrpt::config::CConfigFileMemory> cfg;
  try
  {
    cfg = common::readIniFile(path);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument(std::string("run record: ") + e.what());
  }
  if (!cfg->sectionExists(kSection))
    throw std::invalid_argument("run record '" + path + "': no [run] section (not a run.ini written by swslam)");
  RunRecord r;
  r.program = required(*cfg, "program", path);
  r.version = required(*cfg, "version", path);
  r.input = required(*cfg, "input", path);
  r.use_odometry = flag(*cfg, "odometry", path);
  r.deterministic = flag(*cfg, "deterministic", path);
  r.sensor_label = cfg->read_string(kSection, "sensor_label", "");
  r.scan_topic = cfg->read_string(kSection, "scan_topic", "");
  r.odom_topic = cfg->read_string(kSection, "odom_topic", "");
  r.max_scans = common::readIniCount(*cfg, kSection, "max_scans", "run record '" + path + "'");
  r.throttle_scans = common::readIniCount(*cfg, kSection, "throttle_scans", "run record '" + path + "'");
  try
  {
    r.config = loadConfig(*cfg, {kSection});
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument("run record '" + path + "': " + e.what());
  }
  return r;
}

}  // namespace swslam::app
