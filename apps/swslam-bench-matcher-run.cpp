// libswslam-bench-matcher-run.so: the work of swslam-bench-matcher, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_bench_matcher(const app::BenchMatcherOptions* o)
{
  return app::runBenchMatcher(*o, std::cout, std::cerr);
}
