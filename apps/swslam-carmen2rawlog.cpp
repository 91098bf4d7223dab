// swslam-carmen2rawlog: CARMEN log (plain or .gz) -> observation-only MRPT rawlog, keeping
// each line's own timestamp, plus the reference poses as a TUM file. See doc/carmen.md.

#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-carmen2rawlog", ' ', "0.1");
  TCLAP::ValueArg<std::string> in("i", "input", "Input CARMEN log (*.log, *.log.gz)", true, "",
                                  "carmen.log", cmd);
  TCLAP::ValueArg<std::string> out("o", "output", "Output rawlog (*.rawlog)", true, "",
                                   "out.rawlog", cmd);
  TCLAP::ValueArg<std::string> gt("", "ground-truth",
                                  "Write the scans' reference poses (x y theta) as TUM", false,
                                  "", "gt.tum", cmd);
  TCLAP::ValueArg<int> level("z", "compress-level", "Rawlog gzip level, 0-9 (default 5)", false,
                             5, "0-9", cmd);
  TCLAP::ValueArg<double> max_range("", "max-range",
                                    "Force the maximum range [m] (default: from the log)",
                                    false, 0, "metres", cmd);
  TCLAP::SwitchArg laser_only("", "laser-only", "Drop the odometry (ODOM lines, or the FLASER/RLASER odom_* fields of a log without them)", cmd);
  TCLAP::SwitchArg reference_odometry(
      "", "reference-odometry",
      "Write each scan's reference pose as odometry before it (needs --laser-only "
      "--repair-timestamps): a perfect motion prediction, for evaluation only",
      cmd);
  TCLAP::SwitchArg repair("", "repair-timestamps",
                          "Make each stream's timestamps strictly increasing", cmd);
  TCLAP::SwitchArg overwrite("w", "overwrite", "Overwrite existing output files", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "Print no warnings, only the summary", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::Carmen2RawlogRunOptions o;
  o.input = in.getValue();
  o.output = out.getValue();
  o.ground_truth = gt.getValue();
  o.compress_level = level.getValue();
  o.max_range = max_range.getValue();
  o.laser_only = laser_only.getValue();
  o.repair_timestamps = repair.getValue();
  o.reference_odometry = reference_odometry.getValue();
  o.quiet = quiet.getValue();
  o.overwrite = overwrite.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-carmen2rawlog", swslam_run_carmen2rawlog, o);
}
