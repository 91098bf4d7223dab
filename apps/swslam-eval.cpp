// swslam-eval: trajectory accuracy. See doc/evaluation.md.
//   swslam-eval ate EST.tum GT.tum        ATE after SE(2) alignment, RPE per pose and per metre
//   swslam-eval relations EST.tum F.relations   Kuemmerle et al. relation-based metric
//   swslam-eval consistency EST.tum LOG [--compare OTHER.tum]...   scans' agreement, no truth
//   swslam-eval laser-optimum TRAJ.tum LOG   how far the scans' own constraints pull TRAJ

#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

#include <iostream>

int main(int argc, char** argv)
{
  try
  {
    TCLAP::CmdLine cmd("swslam-eval: trajectory accuracy (ATE, RPE, Kuemmerle relations) and the "
                       "scans' self-consistency at a trajectory's poses, and how far the scans' own constraints "
                       "pull it", ' ', "0.1");
    std::vector<std::string> commands = swslam::app::evalCommands();
    TCLAP::ValuesConstraint<std::string> allowed(commands);
    TCLAP::UnlabeledValueArg<std::string> command("command", "ate | relations | consistency | laser-optimum", true, "",
                                                  &allowed, cmd);
    TCLAP::UnlabeledValueArg<std::string> est("estimate", "Estimated trajectory (TUM)", true, "", "EST.tum", cmd);
    TCLAP::UnlabeledValueArg<std::string> reference(
        "reference", "Ground truth (TUM) for 'ate', relations file for 'relations', the log "
        "(rawlog, CARMEN log, ROS 1 or 2 bag) for 'consistency' and 'laser-optimum'", true, "", "GT.tum|FILE.relations|LOG", cmd);
    TCLAP::ValueArg<double> max_dt("", "max-dt", "Timestamp association tolerance (default 0.01)", false, 0.01,
                                   "seconds", cmd);
    TCLAP::ValueArg<double> segment("", "segment", "RPE segment length along the ground truth (default 1)", false,
                                    1.0, "metres", cmd);
    TCLAP::MultiArg<std::string> compare("", "compare", "consistency: also score this trajectory on the same pairs "
                                         "(repeatable)", false, "OTHER.tum", cmd);
    TCLAP::ValueArg<double> radius("", "radius", "consistency: pairs of scans this close on the estimate (default "
                                   "3); laser-optimum: pairs matched (default [tracking] dense_radius)", false, 3.0,
                                   "metres", cmd);
    TCLAP::ValueArg<long> min_gap("", "min-gap", "consistency: pairs at least this many scored scans apart "
                                  "(default 1)", false, 1, "scans", cmd);
    TCLAP::ValueArg<long> revisit_gap("", "revisit-gap", "consistency: pairs this many scored scans apart are "
                                      "revisits (default 30)", false, 30, "scans", cmd);
    TCLAP::ValueArg<std::string> config("c", "config", "consistency and laser-optimum (required): the run's "
                                        "configuration (how the log is read, PLICP, the graph optimizer)", false, "",
                                        "INI", cmd);
    TCLAP::ValueArg<std::string> label("", "sensor-label", "consistency, laser-optimum: the scans of this sensor "
                                       "(default: the first seen)", false, "", "LABEL", cmd);
    TCLAP::ValueArg<std::string> output("o", "output", "laser-optimum: write the optimum here (TUM, vehicle poses)",
                                        false, "", "OPT.tum", cmd);
    TCLAP::ValueArg<long> stride("", "stride", "consistency, laser-optimum: every K-th scan (default 1)", false, 1,
                                 "K", cmd);
    if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

    swslam::app::EvalOptions o;
    o.command = command.getValue();
    o.estimate = est.getValue();
    o.reference = reference.getValue();
    o.config = config.getValue();
    o.sensor_label = label.getValue();
    o.output = output.getValue();
    o.compare = compare.getValue();
    o.max_dt = max_dt.getValue();
    o.segment = segment.getValue();
    if (radius.isSet()) o.radius = radius.getValue();
    o.min_gap = min_gap.getValue();
    o.revisit_gap = revisit_gap.getValue();
    o.stride = stride.getValue();
    return SWSLAM_RUN_IN_LIBRARY("swslam-eval", swslam_run_eval, o);
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-eval: " << e.what() << "\n";
    return 1;
  }
}
