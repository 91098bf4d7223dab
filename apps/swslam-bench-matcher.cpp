// Benchmark: PLICP vs MRPT's CICP (classic, LM) on scan pairs of a log with reference poses.
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-bench-matcher: PLICP vs MRPT CICP on scan pairs", ' ', "0.1");
  TCLAP::ValueArg<std::string> input("i", "input", "Rawlog with 2D scans", true, "", "LOG.rawlog", cmd);
  TCLAP::ValueArg<std::string> gt("g", "ground-truth", "Reference poses (TUM)", true, "", "GT.tum", cmd);
  TCLAP::ValueArg<size_t> stride("s", "stride", "Pair scans k and k+K", false, 1, "K", cmd);
  TCLAP::ValueArg<std::string> config("c", "config", "Config file ([plicp], [correlative] and [tracking] search rules)", false, "", "INI", cmd);
  TCLAP::ValueArg<std::string> only("m", "method", "Run only this matcher (plicp, plicp+search, cicp-classic, cicp-lm)", false, "", "NAME", cmd);
  TCLAP::SwitchArg floor_arg("f", "floor", "Also time the work of any full-resolution PLICP match before its first step (scan conversion, reference index, one search), and the parts of a pair that plicp+search searches from identity (PLICP, the search's grid, branch and bound)", cmd);
  TCLAP::SwitchArg misses_arg("x", "misses", "Also count the pairs plicp+search puts 5 cm or more off from identity, and those of them whose own scans support the reference (PLICP from it stays, with more inliers or a higher grid score than at the chosen pose)", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::BenchMatcherOptions o;
  o.input = input.getValue();
  o.ground_truth = gt.getValue();
  o.stride = stride.getValue();
  o.config = config.getValue();
  o.method = only.getValue();
  o.floor = floor_arg.getValue();
  o.misses = misses_arg.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-bench-matcher", swslam_run_bench_matcher, o);
}
