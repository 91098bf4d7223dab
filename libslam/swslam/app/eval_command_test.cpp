// swslam-eval's commands: what each prints, and each wrong option named before any work.
#include <swslam/app/eval_command.h>

#include <swslam/common/tum_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_support.h"

using namespace swslam;
using namespace swslam::app;

namespace
{
/** A 20-pose arc, and the same arc moved by 5 cm along y from pose 10 on. */
std::string writeArc(const std::string& dir, const std::string& name, double step_error)
{
  std::vector<common::StampedPose> poses;
  for (int k = 0; k < 20; k++)
    poses.push_back({0.1 * k, mrpt::poses::CPose2D(0.5 * k, k >= 10 ? step_error : 0, 0.01 * k)});
  const std::string path = dir + "/" + name;
  common::writeTum(path, poses);
  return path;
}

std::string value(const std::string& report, const std::string& key)
{
  std::istringstream in(report);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + "=", 0) == 0) return line.substr(key.size() + 1);
  return "";
}
}  // namespace

TEST(EvalCommand, AteOfATrajectoryAgainstItselfIsZeroAndAgainstAStepIsNot)
{
  const std::string dir = test::tempDir("eval_command_ate");
  EvalOptions o;
  o.command = "ate";
  o.estimate = writeArc(dir, "est.tum", 0);
  o.reference = o.estimate;
  std::ostringstream same;
  runEval(o, same, same);
  EXPECT_EQ(value(same.str(), "matched"), "20");
  EXPECT_NEAR(std::stod(value(same.str(), "ate_rmse")), 0, 1e-9);

  o.reference = writeArc(dir, "gt.tum", 0.05);
  std::ostringstream step;
  runEval(o, step, step);
  EXPECT_GT(std::stod(value(step.str(), "ate_rmse")), 0.01);
}

TEST(EvalCommand, AteWarnsWhenPartOfTheEstimateIsNotMatchedByStamp)
{
  // Scans whose stamps stepped back: 200 of 296 poses were scored without a word.
  const std::string dir = test::tempDir("eval_command_unmatched");
  EvalOptions o;
  o.command = "ate";
  o.reference = writeArc(dir, "gt.tum", 0);
  std::vector<common::StampedPose> est;
  for (int k = 0; k < 20; k++)  // poses 12-16 stamped a second back: no ground truth there
    est.push_back({0.1 * k - (k >= 12 && k < 17 ? 1.05 : 0), mrpt::poses::CPose2D(0.5 * k, 0, 0.01 * k)});
  o.estimate = dir + "/est.tum";
  common::writeTum(o.estimate, est);
  std::ostringstream out, err;
  runEval(o, out, err);
  EXPECT_EQ(value(out.str(), "matched"), "15");
  EXPECT_EQ(err.str(), "swslam-eval: warning: " + o.estimate +
                           ": scored 15 of the 20 estimated poses: 5 have no ground-truth pose within 0.01 s of their "
                           "stamp (the estimate's stamps step back or repeat 1 time(s): were its scans' stamps out of "
                           "order?)\n");
  // Every pose matched: no word.
  o.estimate = o.reference;
  std::ostringstream quiet;
  runEval(o, out, quiet);
  EXPECT_EQ(quiet.str(), "");
}

TEST(EvalCommand, WrongOptionsAreNamedBeforeAnyInputIsRead)
{
  const std::string dir = test::tempDir("eval_command_options");
  EvalOptions o;
  o.estimate = writeArc(dir, "est.tum", 0);
  o.reference = dir + "/no-such.log";
  std::ostringstream out;
  const auto message = [&](EvalOptions x) {
    try
    {
      runEval(x, out, out);
    }
    catch (const std::exception& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  o.command = "atee";
  EXPECT_NE(message(o).find("unknown command 'atee'"), std::string::npos);
  o.command = "consistency";
  EXPECT_NE(message(o).find("--config"), std::string::npos);
  o.config = std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini";
  auto bad = o;
  bad.stride = 0;
  EXPECT_NE(message(bad).find("--stride"), std::string::npos);
  bad = o;
  bad.radius = -1;
  EXPECT_NE(message(bad).find("--radius"), std::string::npos);
  o.command = "laser-optimum";
  o.output = dir + "/missing-dir/opt.tum";
  EXPECT_NE(message(o).find("no directory"), std::string::npos);
  EXPECT_TRUE(out.str().empty());
}
