// A run's exit code from its outcome (exit_codes.h).
#include <swslam/app/exit_codes.h>

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

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

TEST(ExitCode, AnExceptionOfTheWorkIsPrintedWithTheProgramsNameAndExitsOne)
{
  std::ostringstream err;
  EXPECT_EQ(exitCodeOf("swslam-x", err, [] { return 4; }), 4);
  EXPECT_EQ(err.str(), "");
  EXPECT_EQ(exitCodeOf("swslam-x", err, []() -> int { throw std::runtime_error("'a.log' is missing"); }), kExitUsage);
  EXPECT_EQ(err.str(), "swslam-x: 'a.log' is missing\n");
}
