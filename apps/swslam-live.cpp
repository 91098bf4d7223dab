// swslam-live: live mapping from a Hokuyo through MRPT's CHokuyoURG (see doc/live.md).
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-live: live 2D LiDAR SLAM from a Hokuyo (SCIP 2.0, serial or Ethernet)", ' ', "0.1");
  TCLAP::ValueArg<std::string> config("c", "config", "swslam config (default: the installed config/default.ini), or one "
                                      "file with the sensor section too", false, "", "INI", cmd);
  TCLAP::ValueArg<std::string> sensor("", "sensor-config", "MRPT rawlog-grabber .ini with the sensor section (e.g. hokuyo_UTM.ini)",
                                      false, "", "INI", cmd);
  TCLAP::ValueArg<std::string> section("s", "sensor-section", "Sensor section (default LASER_2D)", false,
                                       "LASER_2D", "NAME", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Output directory (created if missing)", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> record("r", "record", "Rawlog to record into (default DIR/recording.rawlog)",
                                      false, "", "FILE", cmd);
  TCLAP::ValueArg<double> save("", "save-period", "Rewrite the outputs every S seconds (0: at the end only)",
                               false, 30, "S", cmd);
  TCLAP::ValueArg<double> duration("", "duration", "Stop after S seconds (0: at SIGINT/SIGTERM)", false, 0, "S", cmd);
  TCLAP::ValueArg<double> stall("", "stall-timeout", "Reconnect after S seconds without a scan", false, 2, "S", cmd);
  TCLAP::SwitchArg deterministic("d", "deterministic", "Run the system on the reading thread", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "No status line", cmd);
  TCLAP::SwitchArg no_render("", "no-render", "Skip render.png", cmd);
  TCLAP::ValueArg<std::string> localize("", "localize",
                                        "Localize on this saved session or run folder instead of mapping "
                                        "(doc/localization.md; the config defaults to the map's run.ini)",
                                        false, "", "DIR", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::LiveRunOptions o;
  o.config = config.getValue();
  o.sensor_config = sensor.getValue();
  o.sensor_section = section.getValue();
  o.output = output.getValue();
  o.record = record.getValue();
  o.save_period = save.getValue();
  o.duration = duration.getValue();
  o.stall_timeout = stall.getValue();
  o.deterministic = deterministic.getValue();
  o.status = !quiet.getValue();
  o.render = !no_render.getValue();
  o.localize = localize.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-live", swslam_run_live, o);
}
