// The run's record: each scan placed on the optimized keyframes (run_recorder.h).
#include <swslam/system/run_recorder.h>

#include <swslam/geometry/expect_pose.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::system;
using mrpt::poses::CPose2D;
using swslam::geometry::expectPose;

namespace
{
/** A tracking step on `keyframe` at `relative` (a new keyframe when relative is the identity
 * and `node`), matched with `information`. */
tracking::TrackingStep step(size_t keyframe, const CPose2D& relative, const CPose2D& pose, bool node,
                            const Eigen::Matrix3d& information = Eigen::Matrix3d::Zero())
{
  tracking::TrackingStep s;
  s.keyframe = keyframe;
  s.relative = relative;
  s.pose = pose;
  s.new_keyframe = node;
  s.relative_information = information;
  return s;
}
}  // namespace

TEST(RunRecorder, ScansBetweenKeyframesArePlacedOnBothAndTheLastOnesOnTheirMatch)
{
  // Keyframes 0 at t = 0 and 1 at t = 0.4 s; three scans between them, matched along a road
  // whose walls fix y and heading but nothing fixes x: they stopped (x = 0.05) where the
  // vehicle went on at 2 m/s. Two scans after keyframe 1, matched confidently.
  RunRecorder recorder(tracking::PlacementModel{});
  const Eigen::Matrix3d weak_x = Eigen::Vector3d(1e-2, 1e6, 1e6).asDiagonal();
  const Eigen::Matrix3d strong = Eigen::Vector3d(1e6, 1e6, 1e6).asDiagonal();
  recorder.tracked(0, 0.0, step(0, CPose2D(), CPose2D(), true), 0, 1);
  for (int k = 1; k <= 3; k++)
    recorder.tracked(k, 0.1 * k, step(0, CPose2D(0.05, 0.01, 0), CPose2D(0.05, 0.01, 0), false, weak_x), 0, 1);
  recorder.tracked(4, 0.4, step(1, CPose2D(), CPose2D(0.8, 0, 0), true), 0, 2);
  recorder.tracked(5, 0.5, step(1, CPose2D(0.21, 0, 0), CPose2D(1.01, 0, 0), false, strong), 0, 2);
  recorder.tracked(6, 0.6, step(1, CPose2D(0.39, 0, 0), CPose2D(1.19, 0, 0), false, strong), 0, 2);

  // The graph moved both keyframes: the trajectory follows their optimized poses.
  graph::PoseGraph g;
  const CPose2D a(10, 5, M_PI / 2), b = a + CPose2D(0.8, 0, 0);
  g.addNode(0, a);
  g.addNode(1, b);
  const RunResults r = recorder.results(g, 0, 0);
  ASSERT_EQ(r.trajectory.size(), 7u);
  ASSERT_EQ(r.keyframes.size(), 2u);
  expectPose(r.trajectory[0].pose, a, 1e-12, "keyframe 0");
  expectPose(r.trajectory[4].pose, b, 1e-12, "keyframe 1");
  for (int k = 1; k <= 3; k++)
  {
    const CPose2D rel = r.trajectory[k].pose - a;
    EXPECT_NEAR(rel.x(), 0.2 * k, 1e-3) << "scan " << k << ": along the road, the keyframes' motion";
    EXPECT_NEAR(rel.y(), 0.01, 1e-3) << "scan " << k << ": across it, the match";
  }
  expectPose(r.trajectory[5].pose, b + CPose2D(0.21, 0, 0), 1e-12, "after the last keyframe: the match");
  expectPose(r.trajectory[6].pose, b + CPose2D(0.39, 0, 0), 1e-12, "after the last keyframe: the match");
}

TEST(RunRecorder, AKeyframeTheGraphHasNotReceivedLeavesItsScansWhereTrackingPutThem)
{
  RunRecorder recorder(tracking::PlacementModel{});
  recorder.tracked(0, 0.0, step(0, CPose2D(), CPose2D(), true), 0, 1);
  recorder.tracked(1, 0.1, step(0, CPose2D(0.1, 0, 0), CPose2D(0.1, 0, 0), false), 0, 1);
  recorder.tracked(2, 0.2, step(1, CPose2D(), CPose2D(0.2, 0, 0), true), 0, 2);
  recorder.tracked(3, 0.3, step(1, CPose2D(0.1, 0, 0), CPose2D(0.3, 0.01, 0), false), 0, 2);
  graph::PoseGraph g;  // threaded, mid-run: only keyframe 0 is in the graph, moved
  g.addNode(0, CPose2D(1, 0, 0));
  const RunResults r = recorder.results(g, 0, 0);
  ASSERT_EQ(r.trajectory.size(), 4u);
  expectPose(r.trajectory[1].pose, CPose2D(1.1, 0, 0), 1e-12, "before a keyframe the graph lacks: the match");
  expectPose(r.trajectory[3].pose, CPose2D(0.3, 0.01, 0), 1e-12, "on that keyframe: tracking's pose");
}
