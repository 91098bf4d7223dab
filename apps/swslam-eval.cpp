// swslam-eval: trajectory accuracy. See doc/evaluation.md.
//   swslam-eval ate EST.tum GT.tum        ATE after SE(2) alignment, RPE per pose and per metre
//   swslam-eval relations EST.tum F.relations   Kuemmerle et al. relation-based metric

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <swslam/eval/report.h>

#include <iostream>

int main(int argc, char** argv)
{
  try
  {
    TCLAP::CmdLine cmd("swslam-eval: trajectory accuracy (ATE, RPE, Kuemmerle relations)", ' ',
                       "0.1");
    std::vector<std::string> commands{"ate", "relations"};
    TCLAP::ValuesConstraint<std::string> allowed(commands);
    TCLAP::UnlabeledValueArg<std::string> command("command", "ate | relations", true, "",
                                                  &allowed, cmd);
    TCLAP::UnlabeledValueArg<std::string> est("estimate", "Estimated trajectory (TUM)", true,
                                              "", "EST.tum", cmd);
    TCLAP::UnlabeledValueArg<std::string> reference(
        "reference", "Ground truth (TUM) for 'ate', relations file for 'relations'", true, "",
        "GT.tum|FILE.relations", cmd);
    TCLAP::ValueArg<double> max_dt("", "max-dt", "Timestamp association tolerance (default 0.01)",
                                   false, 0.01, "seconds", cmd);
    TCLAP::ValueArg<double> segment("", "segment", "RPE segment length along the ground truth"
                                    " (default 1)", false, 1.0, "metres", cmd);
    cmd.parse(argc, argv);
    if (!(max_dt.getValue() >= 0)) throw std::runtime_error("--max-dt must be >= 0");
    if (!(segment.getValue() > 0)) throw std::runtime_error("--segment must be > 0");

    const auto estimate = swslam::eval::readNonEmptyTum(est.getValue());
    if (command.getValue() == "ate")
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
