#include <swslam/app/bench_matcher_run.h>

#include <swslam/app/config.h>
#include <swslam/app/exit_codes.h>
#include <swslam/bench/matcher.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace swslam::app
{
int runBenchMatcher(const BenchMatcherOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-bench-matcher", err, [&] {
    plicp::PlicpParams params;
    correlative::CorrelativeParams search;
    tracking::TrackingParams tracking;
    if (!o.config.empty())
    {
      const auto loaded = loadConfig(o.config).system;
      params = loaded.plicp;
      search = loaded.correlative;
      tracking = loaded.tracking;
    }
    if (o.stride < 1) throw std::invalid_argument("--stride must be >= 1");
    const auto data = io::loadScansWithTruth(o.input, common::readTum(o.ground_truth));
    const auto& s0 = *data.scans.front();
    out << "# " << o.input << ": " << data.scans.size() << " scans of " << s0.getScanSize() << " beams over "
        << s0.aperture * 180 / M_PI << " deg, stride " << o.stride << "\n";
    const auto rows = bench::benchmarkMatchers(data, o.stride, params, o.method, search, tracking);
    for (const auto& row : rows) out << bench::formatRow(row) << std::endl;
    if (o.floor)
    {
      out << bench::formatFloor(bench::plicpFloor(data, o.stride, params)) << std::endl;
      out << bench::formatSearchFloor(bench::searchFloor(data, o.stride, params, search, tracking)) << std::endl;
    }
    if (o.misses)
    {
      const auto from_identity = std::find_if(rows.begin(), rows.end(), [](const auto& r) {
        return r.method == "plicp+search" && r.init == "identity";
      });
      if (from_identity == rows.end())
        throw std::invalid_argument("--misses needs the plicp+search rows (no --method, or --method plicp+search)");
      out << bench::formatMisses(bench::explainMisses(data, o.stride, *from_identity, params, search)) << std::endl;
    }
    return kExitOk;
  });
}

}  // namespace swslam::app
