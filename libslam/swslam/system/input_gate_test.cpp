// Where a scan enters: a stamp that repeats or steps back within timestamp_step_back right
// after one that went forward is taken under its own stamp and said; further back, or a clock
// that does not run, is skipped; the latest stamp taken is what the next is judged against.
#include <swslam/system/input_gate.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::system;

namespace
{
sensor::ScanInput scanAt(double t)
{
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
  obs->resizeScan(181);
  obs->aperture = M_PI;
  obs->maxRange = 30;
  for (size_t i = 0; i < 181; ++i) obs->setScanRange(i, 5.0f), obs->setScanRangeValidity(i, true);
  obs->timestamp = mrpt::Clock::fromDouble(t);
  return {obs, {}};
}

FeedStatus admitAt(InputGate& gate, double t)
{
  sensor::ScanInput in = scanAt(t);
  return gate.admit(in).status;
}
}  // namespace

TEST(InputGate, StampsThatRepeatOrStepBackALittleAreTakenFurtherBackSkipped)
{
  SystemOptions options;  // timestamp_step_back 1 s
  InputGate gate(options);
  EXPECT_EQ(admitAt(gate, 100.0), FeedStatus::Accepted);
  EXPECT_EQ(admitAt(gate, 100.2), FeedStatus::Accepted);
  EXPECT_EQ(admitAt(gate, 100.2), FeedStatus::TimestampStepBack);  // repeated
  EXPECT_EQ(admitAt(gate, 100.3), FeedStatus::Accepted);
  EXPECT_EQ(admitAt(gate, 99.4), FeedStatus::TimestampStepBack);   // 0.9 s back
  EXPECT_EQ(admitAt(gate, 100.4), FeedStatus::Accepted);
  EXPECT_EQ(admitAt(gate, 99.3), FeedStatus::TimestampNotIncreasing);  // 1.1 s back
  EXPECT_EQ(admitAt(gate, 100.5), FeedStatus::Accepted);
  sensor::ScanInput in = scanAt(100.5);
  const FeedResult r = gate.admit(in);
  EXPECT_TRUE(r.ok());
  EXPECT_NE(r.message.find("equal to the latest taken"), std::string::npos) << r.message;
}

TEST(InputGate, AClockThatDoesNotRunIsNoJitter)
{
  // Only a scan right after one that went forward may step back: every stamp equal (or two
  // out of step in a row) is skipped from the second on.
  SystemOptions options;
  InputGate gate(options);
  EXPECT_EQ(admitAt(gate, 100.0), FeedStatus::Accepted);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(admitAt(gate, 100.0), FeedStatus::TimestampNotIncreasing) << k;
  EXPECT_EQ(admitAt(gate, 100.1), FeedStatus::Accepted);
  EXPECT_EQ(admitAt(gate, 100.05), FeedStatus::TimestampStepBack);
  EXPECT_EQ(admitAt(gate, 100.05), FeedStatus::TimestampNotIncreasing);
}

TEST(InputGate, WithoutAStepBackOnlyIncreasingStampsAreTaken)
{
  SystemOptions options;
  options.timestamp_step_back = 0;
  InputGate gate(options);
  EXPECT_EQ(admitAt(gate, 100.0), FeedStatus::Accepted);
  EXPECT_EQ(admitAt(gate, 100.0), FeedStatus::TimestampNotIncreasing);
  EXPECT_EQ(admitAt(gate, 99.99), FeedStatus::TimestampNotIncreasing);
  EXPECT_EQ(admitAt(gate, 100.01), FeedStatus::Accepted);
}
