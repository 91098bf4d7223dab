#pragma once
// What a program's exit code says, the same for every swslam program.

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

}  // namespace swslam::app
