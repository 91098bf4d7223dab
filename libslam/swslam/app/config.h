#pragma once
// The whole file a program reads with -c (config/default.ini, doc/configuration.md): the
// system's sections (system/config.h), the input's, [carmen], and swslam-localize's,
// [localization]; written as the two shipped
// files, config/default.ini (the user's keys) and config/expert.ini (the rest).

#include <swslam/common/param_table.h>
#include <swslam/io/carmen_params.h>
#include <swslam/localize/params.h>
#include <swslam/system/config.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace swslam::app
{
struct Config
{
  system::SystemParams system;
  io::CarmenParams carmen;  ///< [carmen]: how CARMEN logs are read
  localize::LocalizationParams localization;  ///< [localization]: swslam-localize

  /** Calls visit(table, parameters) for each section, in file order. */
  template <class C, class Visit>
  static void forEachSection(C& c, Visit visit)
  {
    system::SystemParams::forEachSection(c.system, visit);
    visit(io::CarmenParams::table(), c.carmen);
    visit(localize::LocalizationParams::table(), c.localization);
  }
};

/** Loads every section present, strictly; absent sections and keys keep their defaults.
 * `other_sections` are allowed and left alone (a sensor's [LASER_2D] beside swslam's), and
 * so is [run], so that a run's run.ini (run_record.h) is a configuration.
 * Throws std::invalid_argument naming the section or key that is wrong. */
Config loadConfig(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& other_sections = {});
Config loadConfig(const std::string& ini_path);

/** Every section's keys of one tier, each with its unit, one line of doc and its value in `c`. */
std::string configText(const Config& c, common::Tier tier);

/** config/default.ini (Tier::User) or config/expert.ini (Tier::Expert) as shipped: a header,
 * then configText() of the defaults. */
std::string shippedConfigFile(common::Tier tier);

}  // namespace swslam::app
