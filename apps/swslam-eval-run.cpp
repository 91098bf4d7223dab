// libswslam-eval-run.so: the work of swslam-eval, which loads it after parsing (programs.h).
#include "programs.h"

#include <swslam/app/exit_codes.h>

#include <iostream>

using namespace swslam;

int swslam_run_eval(const app::EvalOptions* o)
{
  return app::exitCodeOf("swslam-eval", std::cerr, [o] {
    app::runEval(*o, std::cout, std::cerr);
    return 0;
  });
}
