// swslam-bench-localize: localization on a saved map scored against reference poses
// (doc/localization.md, Figures; scripts/bench-localize.sh).
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-bench-localize: localization on a saved map against reference poses", ' ', "0.1");
  TCLAP::ValueArg<std::string> map("m", "map", "A saved session or a swslam run folder", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> map_truth("", "map-truth", "Reference poses (TUM) of the map's run", true, "", "TUM",
                                         cmd);
  TCLAP::ValueArg<std::string> input("i", "input", "Log to localize", true, "", "LOG", cmd);
  TCLAP::ValueArg<std::string> truth("t", "truth", "Its reference poses (TUM)", true, "", "TUM", cmd);
  TCLAP::ValueArg<std::string> elsewhere("", "elsewhere", "A log of another place, which must stay lost", false, "",
                                         "LOG", cmd);
  TCLAP::ValueArg<long long> starts("", "starts", "Random starts (0: none)", false, 100, "N", cmd);
  TCLAP::ValueArg<long long> seed("", "seed", "Seed of the random starts", false, 1, "N", cmd);
  TCLAP::ValueArg<double> window("", "window", "Log time a start has to relocalize in [s]", false, 2.0, "S", cmd);
  TCLAP::ValueArg<double> follow("", "follow", "Log time tracked and scored after a relocalization [s]", false, 5.0,
                                 "S", cmd);
  TCLAP::SwitchArg no_odometry("", "no-odometry", "Ignore the log's odometry", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::BenchLocalizeOptions o;
  o.map = map.getValue();
  o.map_truth = map_truth.getValue();
  o.input = input.getValue();
  o.truth = truth.getValue();
  o.elsewhere = elsewhere.getValue();
  try
  {
    o.starts = swslam::cli::count(starts, 0);
    o.seed = static_cast<unsigned>(swslam::cli::count(seed, 0));
    if (!(window.getValue() > 0 && window.getValue() < 1e6) || !(follow.getValue() >= 0 && follow.getValue() < 1e6))
      throw std::invalid_argument("--window must be in (0, 1e6) s and --follow in [0, 1e6) s");
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "swslam-bench-localize: " << e.what() << "\n";
    return 1;
  }
  o.window = window.getValue();
  o.follow = follow.getValue();
  o.use_odometry = !no_odometry.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-bench-localize", swslam_run_bench_localize, o);
}
