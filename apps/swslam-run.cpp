// libswslam-run.so: the work of swslam, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_offline(const app::OfflineRunOptions* o) { return app::runOffline(*o, std::cout, std::cerr); }
