// libswslam-localize-run.so: the work of swslam-localize, which loads it after parsing (programs.h).
#include "programs.h"

#include <iostream>

using namespace swslam;

int swslam_run_localize(const app::LocalizeOptions* o) { return app::runLocalize(*o, std::cout, std::cerr); }
