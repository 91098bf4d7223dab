// Benchmark: PLICP vs MRPT's CICP (classic, LM) on scan pairs of a log with reference poses.
#include "cli.h"
#include <swslam/bench/matcher.h>
#include <swslam/app/config.h>


#include <algorithm>
#include <iostream>
#include <stdexcept>

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
  try
  {
    if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
    swslam::plicp::PlicpParams params;
    swslam::correlative::CorrelativeParams search;
    swslam::tracking::TrackingParams tracking;
    if (!config.getValue().empty())
    {
      const auto loaded = swslam::app::loadConfig(config.getValue()).system;
      params = loaded.plicp;
      search = loaded.correlative;
      tracking = loaded.tracking;
    }
    if (stride.getValue() < 1) throw std::invalid_argument("--stride must be >= 1");
    const auto data = swslam::io::loadScansWithTruth(input.getValue(), swslam::common::readTum(gt.getValue()));
    const auto& s0 = *data.scans.front();
    std::cout << "# " << input.getValue() << ": " << data.scans.size() << " scans of "
              << s0.getScanSize() << " beams over " << s0.aperture * 180 / M_PI << " deg, stride "
              << stride.getValue() << "\n";
    const auto rows = swslam::bench::benchmarkMatchers(data, stride.getValue(), params, only.getValue(), search, tracking);
    for (const auto& row : rows) std::cout << swslam::bench::formatRow(row) << std::endl;
    if (floor_arg.getValue())
    {
      std::cout << swslam::bench::formatFloor(swslam::bench::plicpFloor(data, stride.getValue(), params)) << std::endl;
      std::cout << swslam::bench::formatSearchFloor(swslam::bench::searchFloor(data, stride.getValue(), params, search, tracking))
                << std::endl;
    }
    if (misses_arg.getValue())
    {
      const auto from_identity = std::find_if(rows.begin(), rows.end(), [](const auto& r) {
        return r.method == "plicp+search" && r.init == "identity";
      });
      if (from_identity == rows.end())
        throw std::invalid_argument("--misses needs the plicp+search rows (no --method, or --method plicp+search)");
      std::cout << swslam::bench::formatMisses(
                       swslam::bench::explainMisses(data, stride.getValue(), *from_identity, params, search))
                << std::endl;
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-bench-matcher: " << e.what() << "\n";
    return 1;
  }
}
