#include <swslam/localize/map_nodes.h>

#include <gtest/gtest.h>

#include "support/localize_test_support.h"

using namespace swslam;
using mrpt::poses::CPose2D;

TEST(MapNodes, NearestWeighsDistanceAndHeading)
{
  const auto m = test::savedWorldMap(test::roomWorld(), {CPose2D(-5, 0, 0), CPose2D(0, 0, 0), CPose2D(0.5, 0, M_PI)});
  const localize::MapNodes nodes(m.poses, m.scans, plicp::PlicpParams());
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_NEAR(nodes.sensorPose(1).x(), 0.3, 1e-12);  // the mounting, 0.3 m ahead
  EXPECT_EQ(nodes.nearest(CPose2D(0.3, 0, 0), 5.0), 1u);
  // Facing back, the node at 0.5 facing back is nearer than the one at 0 facing ahead.
  EXPECT_EQ(nodes.nearest(CPose2D(0.3, 0, M_PI), 5.0), 2u);
  EXPECT_EQ(nodes.nearest(CPose2D(-4, 1, 0), 5.0), 0u);
}

TEST(MapNodes, RaysAroundANodeAreInItsSensorFrame)
{
  const auto m = test::savedWorldMap(test::roomWorld(), {CPose2D(0, 0, 0), CPose2D(1, 0, M_PI / 2), CPose2D(-9, 0, 0)});
  const localize::MapNodes nodes(m.poses, m.scans, plicp::PlicpParams());
  const auto rays = nodes.raysAround(0, 2, 30);  // node 0 and its nearest, node 1; not node 2
  ASSERT_EQ(rays.size(), m.scans[0].size() + m.scans[1].size());
  EXPECT_TRUE(rays.front().origin.isZero());
  // Node 1's sensor, at (1.0, 0.3) facing +y, is at (0.7, 0) seen from node 0's at (0.3, 0).
  EXPECT_NEAR(rays.back().origin.x(), 0.7, 1e-9);
  EXPECT_NEAR(rays.back().origin.y(), 0.3, 1e-9);
  // Every hit lies on the room's walls as node 0's sensor sees them: the north wall at y = 6
  // (x < 7), seen from the sensor at (0.3, 0), is at y = 6 in its frame.
  size_t on_north = 0;
  for (const auto& r : rays)
    if (std::abs(r.hit.y() - 6) < 0.05 && r.hit.x() < 6.5) on_north++;
  EXPECT_GT(on_north, 50u);
}

TEST(MapNodes, CountsMustAgree)
{
  EXPECT_THROW(localize::MapNodes({CPose2D()}, {}, plicp::PlicpParams()), std::invalid_argument);
  EXPECT_THROW(localize::MapNodes({}, {}, plicp::PlicpParams()), std::invalid_argument);
}

TEST(MapNodes, AFarNodeLendsNoRaysEvenWhenFewAreNear)
{
  // Three nodes asked for; the third is 100 m away, beyond twice the rays' 30 m.
  const auto m = test::savedWorldMap(test::roomWorld(), {CPose2D(0, 0, 0), CPose2D(1, 0, 0), CPose2D(100, 0, 0)});
  const localize::MapNodes nodes(m.poses, m.scans, plicp::PlicpParams());
  EXPECT_EQ(nodes.raysAround(0, 3, 30).size(), m.scans[0].size() + m.scans[1].size());
}

TEST(MapNodes, NodesOfTwoSensorsAreANamedError)
{
  auto m = test::savedWorldMap(test::roomWorld(), {CPose2D(0, 0, 0), CPose2D(1, 0, 0)});
  m.scans[1].sensor_pose = CPose2D(0.5, 0, 0);
  EXPECT_NE(test::errorOf([&] { localize::MapNodes(m.poses, m.scans, plicp::PlicpParams()); })
                .find("node 1's scan comes from another sensor"),
            std::string::npos);
}
