#include <swslam/app/bench_map_run.h>

#include <swslam/app/config.h>
#include <swslam/app/exit_codes.h>
#include <swslam/bench/map_builder.h>
#include <swslam/common/tum_io.h>
#include <swslam/map/outputs.h>

#include <ostream>

namespace swslam::app
{
int runBenchMap(const BenchMapOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-bench-map", err, [&] {
    map::MapParams params;
    if (!o.config.empty()) params = loadConfig(o.config).system.map;
    const auto data = io::loadScansWithTruth(o.input, common::readTum(o.ground_truth));
    map::MapBuilder builder(params);
    const auto f = bench::benchmarkMapBuilder(data, o.node_every, builder);
    out << "# " << o.input << ", resolution " << params.resolution << " m\n" << bench::formatFigures(f);
    if (!o.output.empty())
    {
      map::Overlay overlay;
      overlay.trajectory = data.truth;
      for (const auto& problem : map::writeMapOutputs(o.output, builder.snapshot(), params, overlay))
        err << "swslam-bench-map: " << problem.file << ": " << problem.message << "\n";
    }
    return kExitOk;
  });
}

}  // namespace swslam::app
