// libswslam-bench-localize-run.so: the work of swslam-bench-localize, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_bench_localize(const app::BenchLocalizeOptions* o)
{
  return app::runBenchLocalize(*o, std::cout, std::cerr);
}
