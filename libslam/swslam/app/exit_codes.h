#pragma once
// What a program's exit code says, the same for every swslam program, and how a run's
// outcome makes it.

#include <functional>
#include <iosfwd>

namespace swslam::app
{
/** Exit codes of the programs' runs (runOffline, runLive). */
enum ExitCode : int
{
  kExitOk = 0,
  kExitUsage = 1,        ///< bad config / options / unreadable input: nothing was written
  kExitInputError = 2,   ///< an input broke off (corrupt entry), gave no usable scan, or a ground
                         ///< truth does not overlap the run: outputs hold what was read, if anything
  kExitModuleError = 3,  ///< a module failed: outputs hold what was processed
  kExitOutputError = 4,  ///< some output could not be written
  kExitInterrupted = 130 ///< SIGINT/SIGTERM: outputs hold what was processed
};

/** What went wrong in a run, noted as the run finds out (after its configuration, input and
 * output folder opened: a failure there is kExitUsage at once). */
struct RunOutcome
{
  bool outputs_lost = false;      ///< no output could be written (the folder failed)
  bool interrupted = false;       ///< stopped by SIGINT/SIGTERM (offline; a live run ends so)
  bool input_failed = false;      ///< the input broke off, or most of its stamps were unusable
  bool module_failed = false;     ///< a module failed
  bool nothing_to_map = false;    ///< no scan was tracked, or none had a valid ray
  bool truth_unusable = false;    ///< the ground truth does not overlap the run
  bool outputs_failed = false;    ///< some output could not be written
};

/** The exit code of a run: the first of outputs lost (kExitOutputError), interrupted,
 * input failed, module failed, nothing to map or an unusable ground truth (kExitInputError),
 * some outputs failed; else kExitOk. */
ExitCode exitCode(const RunOutcome& o);

/** Runs a program's work and returns its exit code; an exception it throws is printed to `err`
 * as "PROGRAM: what" and makes kExitUsage. */
int exitCodeOf(const char* program, std::ostream& err, const std::function<int()>& work);

}  // namespace swslam::app
