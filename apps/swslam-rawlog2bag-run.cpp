// libswslam-rawlog2bag-run.so: the work of swslam-rawlog2bag, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_rawlog2bag(const app::Rawlog2BagRunOptions* o)
{
  return app::runRawlog2Bag(*o, std::cout, std::cerr);
}
