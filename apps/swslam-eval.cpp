// swslam-eval: trajectory accuracy. See doc/evaluation.md.
//   swslam-eval ate EST.tum GT.tum        ATE after SE(2) alignment, RPE per pose and per metre
//   swslam-eval relations EST.tum F.relations   Kuemmerle et al. relation-based metric
//   swslam-eval consistency EST.tum LOG [--compare OTHER.tum]...   scans' agreement, no truth
//   swslam-eval laser-optimum TRAJ.tum LOG   how far the scans' own constraints pull TRAJ

#include "cli.h"
#include <swslam/eval/consistency.h>
#include <swslam/eval/laser_optimum.h>
#include <swslam/eval/report.h>
#include <swslam/system_config.h>

#include <filesystem>
#include <iostream>

int main(int argc, char** argv)
{
  try
  {
    TCLAP::CmdLine cmd("swslam-eval: trajectory accuracy (ATE, RPE, Kuemmerle relations) and the "
                       "scans' self-consistency at a trajectory's poses, and how far the scans' own constraints "
                       "pull it", ' ', "0.1");
    std::vector<std::string> commands{"ate", "relations", "consistency", "laser-optimum"};
    TCLAP::ValuesConstraint<std::string> allowed(commands);
    TCLAP::UnlabeledValueArg<std::string> command("command", "ate | relations | consistency | laser-optimum", true, "",
                                                  &allowed, cmd);
    TCLAP::UnlabeledValueArg<std::string> est("estimate", "Estimated trajectory (TUM)", true,
                                              "", "EST.tum", cmd);
    TCLAP::UnlabeledValueArg<std::string> reference(
        "reference", "Ground truth (TUM) for 'ate', relations file for 'relations', the log "
        "(rawlog or CARMEN) for 'consistency' and 'laser-optimum'", true, "", "GT.tum|FILE.relations|LOG", cmd);
    TCLAP::ValueArg<double> max_dt("", "max-dt", "Timestamp association tolerance (default 0.01)",
                                   false, 0.01, "seconds", cmd);
    TCLAP::ValueArg<double> segment("", "segment", "RPE segment length along the ground truth"
                                    " (default 1)", false, 1.0, "metres", cmd);
    TCLAP::MultiArg<std::string> compare("", "compare", "consistency: also score this trajectory "
                                         "on the same pairs (repeatable)", false, "OTHER.tum", cmd);
    TCLAP::ValueArg<double> radius("", "radius", "consistency: pairs of scans this close on the "
                                   "estimate (default 3); laser-optimum: pairs matched (default "
                                   "[tracking] dense_radius)", false, 3.0, "metres", cmd);
    TCLAP::ValueArg<long> min_gap("", "min-gap", "consistency: pairs at least this many scored "
                                  "scans apart (default 1)", false, 1, "scans", cmd);
    TCLAP::ValueArg<long> revisit_gap("", "revisit-gap", "consistency: pairs this many scored scans "
                                      "apart are revisits (default 30)", false, 30, "scans", cmd);
    TCLAP::ValueArg<std::string> config("c", "config", "consistency and laser-optimum (required): "
                                        "the run's configuration (how the log is read, PLICP, "
                                        "the graph optimizer)", false, "", "INI", cmd);
    TCLAP::ValueArg<std::string> label("", "sensor-label", "consistency, laser-optimum: the scans of this sensor "
                                       "(default: the first seen)", false, "", "LABEL", cmd);
    TCLAP::ValueArg<std::string> output("o", "output", "laser-optimum: write the optimum here "
                                        "(TUM, vehicle poses)", false, "", "OPT.tum", cmd);
    TCLAP::ValueArg<long> stride("", "stride", "consistency, laser-optimum: every K-th scan (default 1)", false, 1,
                                 "K", cmd);
    if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
    if (!(max_dt.getValue() >= 0)) throw std::runtime_error("--max-dt must be >= 0");
    if (!(segment.getValue() > 0)) throw std::runtime_error("--segment must be > 0");

    const auto estimate = swslam::eval::readNonEmptyTum(est.getValue());
    if (command.getValue() == "laser-optimum")
    {
      if (config.getValue().empty())
        throw std::runtime_error("laser-optimum needs --config: the run's configuration says how "
                                 "the log is read and matched");
      const auto params = swslam::loadSystemParams(config.getValue());
      auto options = swslam::eval::laserOptimumOptions(params.tracking, params.loop_closure);
      if (stride.getValue() < 1) throw std::runtime_error("--stride must be >= 1");
      if (radius.isSet()) options.radius = radius.getValue();
      if (!(options.radius > 0))
        throw std::runtime_error(radius.isSet() ? "--radius must be > 0"
                                                : "[tracking] dense_radius is 0: pass --radius");
      // Fail before the matching (minutes on a long log) rather than after it.
      if (!output.getValue().empty())
      {
        const auto out_dir = std::filesystem::absolute(output.getValue()).parent_path();
        if (!std::filesystem::is_directory(out_dir))
          throw std::runtime_error("cannot write '" + output.getValue() + "': no directory '" +
                                   out_dir.string() + "'");
      }
      std::cout << swslam::eval::laserOptimumReport(reference.getValue(), estimate, params.plicp,
                                                    params.graph_optimizer, options,
                                                    max_dt.getValue(),
                                                    static_cast<size_t>(stride.getValue()),
                                                    params.tracking.min_range,
                                                    params.carmen, label.getValue(),
                                                    output.getValue());
    }
    else if (command.getValue() == "consistency")
    {
      if (!(radius.getValue() > 0)) throw std::runtime_error("--radius must be > 0");
      if (min_gap.getValue() < 0 || revisit_gap.getValue() < 0 || stride.getValue() < 1)
        throw std::runtime_error("--min-gap and --revisit-gap must be >= 0, --stride >= 1");
      if (config.getValue().empty())
        throw std::runtime_error("consistency needs --config: the run's configuration says how "
                                 "the log is read");
      const auto params = swslam::loadSystemParams(config.getValue());
      std::vector<std::string> names{est.getValue()};
      std::vector<std::vector<swslam::StampedPose>> trajectories{estimate};
      for (const auto& other : compare.getValue())
      {
        names.push_back(other);
        trajectories.push_back(swslam::eval::readNonEmptyTum(other));
      }
      swslam::eval::ConsistencyOptions options;
      options.radius = radius.getValue();
      options.min_gap = static_cast<size_t>(min_gap.getValue());
      options.revisit_gap = static_cast<size_t>(revisit_gap.getValue());
      options.min_segment = params.plicp.min_segment_length;
      std::cout << swslam::eval::consistencyReport(reference.getValue(), names, trajectories, options,
                                                   max_dt.getValue(),
                                                   static_cast<size_t>(stride.getValue()),
                                                   params.tracking.min_range, params.carmen,
                                                   label.getValue());
    }
    else if (command.getValue() == "ate")
    {
      const auto truth = swslam::eval::readNonEmptyTum(reference.getValue());
      std::cout << swslam::eval::formatTrajectoryEvaluation(swslam::eval::evaluateTrajectory(
          estimate, truth, max_dt.getValue(), segment.getValue()));
    }
    else
    {
      const auto relations = swslam::eval::readRelations(reference.getValue());
      std::cout << swslam::eval::formatRelationsResult(
          swslam::eval::evaluateRelations(estimate, relations, max_dt.getValue()));
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-eval: " << e.what() << "\n";
    return 1;
  }
}
