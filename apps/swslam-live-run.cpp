// libswslam-live-run.so: the work of swslam-live, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_live(const app::LiveRunOptions* o) { return app::runLive(*o, std::cout, std::cerr); }
