// libswslam-regen-map-run.so: the work of swslam-regen-map, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_regen_map(const app::RegenMapOptions* o) { return app::runRegenMap(*o, std::cout, std::cerr); }
