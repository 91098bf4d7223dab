#include <swslam/app/exit_codes.h>

#include <exception>
#include <ostream>

namespace swslam::app
{
ExitCode exitCode(const RunOutcome& o)
{
  if (o.outputs_lost) return kExitOutputError;
  if (o.interrupted) return kExitInterrupted;
  if (o.input_failed) return kExitInputError;
  if (o.module_failed) return kExitModuleError;
  if (o.nothing_to_map || o.truth_unusable) return kExitInputError;
  if (o.outputs_failed) return kExitOutputError;
  return kExitOk;
}

int exitCodeOf(const char* program, std::ostream& err, const std::function<int()>& work)
{
  try
  {
    return work();
  }
  catch (const std::exception& e)
  {
    err << program << ": " << e.what() << "\n";
    return kExitUsage;
  }
}

}  // namespace swslam::app
