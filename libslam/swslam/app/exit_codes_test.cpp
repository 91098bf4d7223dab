// A run's exit code from its outcome (exit_codes.h).
#include <swslam/app/exit_codes.h>

#include <gtest/gtest.h>

using namespace swslam::app;

TEST(ExitCode, TheFirstProblemInOrderOfWeightMakesTheCode)
{
  EXPECT_EQ(exitCode({}), kExitOk);
  RunOutcome o;
  o.outputs_failed = true;
  EXPECT_EQ(exitCode(o), kExitOutputError);
  o.truth_unusable = true;
  EXPECT_EQ(exitCode(o), kExitInputError);
  o.module_failed = true;
  EXPECT_EQ(exitCode(o), kExitModuleError);
  o.input_failed = true;
  EXPECT_EQ(exitCode(o), kExitInputError);
  o.interrupted = true;
  EXPECT_EQ(exitCode(o), kExitInterrupted);
  o.outputs_lost = true;
  EXPECT_EQ(exitCode(o), kExitOutputError);
  RunOutcome empty;
  empty.nothing_to_map = true;
  EXPECT_EQ(exitCode(empty), kExitInputError);
  empty.module_failed = true;
  EXPECT_EQ(exitCode(empty), kExitModuleError);
}
