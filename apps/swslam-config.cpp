// swslam-config: prints the configuration's keys of one tier with their values, from the
// defaults (the shipped config/default.ini and config/expert.ini are its output) or from a
// file, which it checks strictly as every program does (doc/configuration.md).
#include "cli.h"

#include <swslam/app/default_config.h>
#include <swslam/app/config.h>

#include <iostream>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-config: the configuration's keys with their units, docs and values", ' ', "0.1");
  TCLAP::ValueArg<std::string> config(
      "c", "config", "Check this file and print its values (default: print the shipped file of the tier)", false, "",
      "INI", cmd);
  std::vector<std::string> tiers{"user", "expert", "all"};
  TCLAP::ValuesConstraint<std::string> allowed(tiers);
  TCLAP::ValueArg<std::string> tier("t", "tier", "user: the keys config/default.ini shows; expert: the rest", false,
                                    "user", &allowed, cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
  using swslam::common::Tier;
  const std::vector<Tier> printed = tier.getValue() == "user"     ? std::vector<Tier>{Tier::User}
                                    : tier.getValue() == "expert" ? std::vector<Tier>{Tier::Expert}
                                                                  : std::vector<Tier>{Tier::User, Tier::Expert};
  try
  {
    if (config.getValue().empty() && printed.size() == 1)
    {
      std::cout << swslam::app::shippedConfigFile(printed.front());
      return 0;
    }
    const auto params = swslam::app::loadConfig(swslam::app::configOrDefault(config.getValue()));
    for (const Tier t : printed) std::cout << swslam::app::configText(params, t) << "\n";
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-config: " << e.what() << "\n";
    return 1;
  }
}
