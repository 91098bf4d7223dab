// libswslam-carmen2rawlog-run.so: the work of swslam-carmen2rawlog, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_carmen2rawlog(const app::Carmen2RawlogRunOptions* o)
{
  return app::runCarmen2Rawlog(*o, std::cout, std::cerr);
}
