// Where a scan enters: stamps that repeat or step back within timestamp_step_back are taken
// under their own stamp and said, further back they are skipped, and the latest stamp taken is
// what the next is judged against.
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
  EXPECT_EQ(admitAt(gate, 99.9), FeedStatus::TimestampStepBack);   // 0.3 s back
  // Judged against the latest taken (100.2), not the one before: 99.3 is 0.9 s back, 99.1 1.1 s.
  EXPECT_EQ(admitAt(gate, 99.3), FeedStatus::TimestampStepBack);
  EXPECT_EQ(admitAt(gate, 99.1), FeedStatus::TimestampNotIncreasing);
  EXPECT_EQ(admitAt(gate, 100.3), FeedStatus::Accepted);
  sensor::ScanInput in = scanAt(100.3);
  const FeedResult r = gate.admit(in);
  EXPECT_TRUE(r.ok());
  EXPECT_NE(r.message.find("equal to the latest taken"), std::string::npos) << r.message;
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
