// libswslam-sim-run.so: the work of swslam-sim, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_sim(const app::SimOptions* o) { return app::runSim(*o, std::cout, std::cerr); }
