// libswslam-bench-map-run.so: the work of swslam-bench-map, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_bench_map(const app::BenchMapOptions* o) { return app::runBenchMap(*o, std::cout, std::cerr); }
