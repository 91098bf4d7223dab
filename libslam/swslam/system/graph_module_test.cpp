// GraphModule: each node enters the graph placed on the graph's estimate of the previous node
// and goes to the map at its optimized pose; a loop verified by PLICP pulls a drifted chain
// back; an edge the graph refuses is counted, not fatal; nodes out of order are an error;
// a wrong consecutive edge (90 degrees) against three true loops is switched off and the
// loop comes back.
#include <swslam/system/config.h>
#include <swslam/system/graph_module.h>

#include <mrpt/core/bits_math.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "room_loop.h"

using namespace swslam;
using namespace swslam::system;
using mrpt::poses::CPose2D;

namespace
{
graph::Constraint consecutive(size_t to, const CPose2D& z)
{
  graph::Constraint e;
  e.from = to - 1;
  e.to = to;
  e.z = z;
  e.information = Eigen::Vector3d(400, 400, 4000).asDiagonal();
  return e;
}

/** Node `id` of the room loop, tracked at `tracked`, with `edges`. */
NewNode roomNode(const test::RoomLoop& room, size_t id, const CPose2D& tracked, std::vector<graph::Constraint> edges)
{
  NewNode n;
  n.scan = 10 * id;
  n.keyframe.id = id;
  n.keyframe.pose = tracked;
  n.keyframe.scan = std::make_shared<const plicp::ReferenceScan>(room.scans[id]);
  n.edges = std::move(edges);
  return n;
}

/** Drives the 16 nodes round the room with every consecutive measurement turned by `bias`,
 * and returns how far the last node ends from its true pose. */
double lastNodeError(bool loops, double bias, size_t* loop_count = nullptr)
{
  const test::RoomLoop room;
  loop::LoopClosureParams lp;
  lp.enabled = loops;
  lp.min_index_gap = 10;
  lp.consistency_window = 0;
  GraphModule g(graph::GraphOptimizerParams(), lp, plicp::PlicpParams());
  CPose2D tracked = room.poses[0];
  for (size_t id = 0; id < room.poses.size(); id++)
  {
    std::vector<graph::Constraint> edges;
    if (id > 0)
    {
      const CPose2D z = (room.poses[id] - room.poses[id - 1]) + CPose2D(0, 0, bias);
      tracked = tracked + z;
      edges.push_back(consecutive(id, z));
    }
    g.addNode(roomNode(room, id, tracked, edges));
  }
  const auto last = g.optimizeAll(999).poses.at(room.poses.size() - 1);
  if (loop_count) *loop_count = g.loopCount();
  return (last - room.poses.back()).norm();
}
}  // namespace

TEST(GraphModule, ANodeIsPlacedOnTheGraphsPreviousNodeAndMappedAtItsOptimizedPose)
{
  const test::RoomLoop room;
  GraphModule g{graph::GraphOptimizerParams(), loop::LoopClosureParams(), plicp::PlicpParams()};
  const GraphStep first = g.addNode(roomNode(room, 0, room.poses[0], {}));
  ASSERT_TRUE(first.insert);
  EXPECT_EQ(first.insert->id, 0u);
  EXPECT_EQ(first.insert->scan, 0u);
  // The tracker's pose of node 1 is 1 m off; the graph places it by its edge instead.
  const CPose2D z = room.poses[1] - room.poses[0];
  const GraphStep second = g.addNode(roomNode(room, 1, room.poses[1] + CPose2D(1, 0, 0), {consecutive(1, z)}));
  ASSERT_TRUE(second.insert);
  EXPECT_EQ(second.node, 1u);
  EXPECT_LT((second.insert->pose - room.poses[1]).norm(), 1e-6);
  const auto graph = g.graphCopy();
  EXPECT_EQ(graph.nodeCount(), 2u);
  EXPECT_EQ(graph.edgeCount(), 1u);
  EXPECT_LT((graph.pose(1) - second.insert->pose).norm(), 1e-9);
}

TEST(GraphModule, AnEdgeTheGraphRefusesIsCountedAndTheRunGoesOn)
{
  const test::RoomLoop room;
  GraphModule g{graph::GraphOptimizerParams(), loop::LoopClosureParams(), plicp::PlicpParams()};
  g.addNode(roomNode(room, 0, room.poses[0], {}));
  auto good = consecutive(1, room.poses[1] - room.poses[0]);
  auto bad = good;
  bad.from = 0;
  bad.kind = graph::EdgeKind::DenseNeighbour;
  bad.z = CPose2D(NAN, 0, 0);
  const GraphStep step = g.addNode(roomNode(room, 1, room.poses[1], {good, bad}));
  EXPECT_EQ(step.edges_rejected, 1u);
  EXPECT_EQ(g.graphCopy().edgeCount(), 1u);
  EXPECT_THROW(g.addNode(roomNode(room, 5, room.poses[5], {})), std::logic_error);
}

TEST(GraphModule, AVerifiedLoopPullsADriftedChainBack)
{
  const double bias = mrpt::DEG2RAD(0.3);
  size_t loops = 0;
  const double without = lastNodeError(false, bias);
  const double with = lastNodeError(true, bias, &loops);
  EXPECT_GT(without, 0.1);
  EXPECT_GT(loops, 0u);
  EXPECT_LT(with, 0.3 * without) << "without loops " << without << " m, with " << with << " m";
}

TEST(GraphModule, APlantedFalseLoopIsSwitchedOffAndTheLoopStaysRight)
{
  // The room loop with true consecutive edges, and at node 12 a false loop to node 2 (2 m and
  // 30 degrees off, with the information of a confident loop). Graduated non-convexity and the
  // adaptive kernel (every other setting as in config/default.ini: consecutive edges robustified
  // too) switch it off, and the loop stays where it is; the fixed kernel (today's default)
  // switches it off too but still bends the loop (0.38 m at node 12).
  const test::RoomLoop room;
  for (const auto schedule : {graph::KernelSchedule::Gnc, graph::KernelSchedule::Adaptive})
  {
  SCOPED_TRACE(graph::kernelScheduleName(schedule));
  graph::GraphOptimizerParams gp;
  gp.kernel_schedule = schedule;
  GraphModule g{gp, loop::LoopClosureParams(), plicp::PlicpParams()};
  size_t false_edge = 0;
  for (size_t id = 0; id < room.poses.size(); id++)
  {
    std::vector<graph::Constraint> edges;
    if (id > 0) edges.push_back(consecutive(id, room.poses[id] - room.poses[id - 1]));
    if (id == 12)
    {
      graph::Constraint wrong = consecutive(12, (room.poses[12] - room.poses[2]) + CPose2D(2, 0, mrpt::DEG2RAD(30)));
      wrong.from = 2;
      wrong.kind = graph::EdgeKind::Loop;
      false_edge = g.graphCopy().edgeCount() + 1;  // after node 12's consecutive edge
      edges.push_back(wrong);
    }
    g.addNode(roomNode(room, id, room.poses[id], edges));
  }
  const GraphStep end = g.optimizeAll(999);
  EXPECT_EQ(end.report.switched_off, std::vector<size_t>{false_edge});
  const auto graph = g.graphCopy();
  for (size_t id = 0; id < room.poses.size(); id++)
    EXPECT_LT((graph.pose(id) - room.poses[id]).norm(), 0.05) << "node " << id;
  }
}

namespace
{
struct WrongEdgeRun
{
  double worst = 0;               ///< [m] largest node error after the final optimization
  size_t worst_node = 0;
  std::vector<size_t> switched_off;
  size_t wrong_edge = 0;          ///< the planted edge's index
};

/** The room loop with true consecutive edges but node 8's, turned by 90 degrees (the tracker
 * placed node 8 and every node after it on that turn), and three true loops from nodes 14 and
 * 15 back to nodes 0 and 1 (a revisit measured by PLICP, with the information of the
 * consecutive edges). */
WrongEdgeRun wrongConsecutiveEdge(const SystemParams& params)
{
  const test::RoomLoop room;
  GraphModule g{params.graph_optimizer, params.loop_closure, params.plicp};
  WrongEdgeRun run;
  const auto loop = [&](size_t from, size_t to) {
    graph::Constraint e = consecutive(to, room.poses[to] - room.poses[from]);
    e.from = from;
    e.kind = graph::EdgeKind::Loop;
    return e;
  };
  CPose2D tracked = room.poses[0];
  for (size_t id = 0; id < room.poses.size(); id++)
  {
    std::vector<graph::Constraint> edges;
    if (id > 0)
    {
      CPose2D z = room.poses[id] - room.poses[id - 1];
      if (id == 8)
      {
        z = z + CPose2D(0, 0, M_PI / 2);
        run.wrong_edge = g.graphCopy().edgeCount();
      }
      tracked = tracked + z;
      edges.push_back(consecutive(id, z));
    }
    if (id == 14) edges.push_back(loop(0, 14));
    if (id == 15)
    {
      edges.push_back(loop(0, 15));
      edges.push_back(loop(1, 15));
    }
    g.addNode(roomNode(room, id, tracked, edges));
  }
  const GraphStep end = g.optimizeAll(999);
  run.switched_off = end.report.switched_off;
  const auto graph = g.graphCopy();
  for (size_t id = 0; id < room.poses.size(); id++)
  {
    const double e = (graph.pose(id) - room.poses[id]).norm();
    if (e > run.worst) run.worst = e, run.worst_node = id;
  }
  return run;
}
}  // namespace

TEST(GraphModule, APlantedWrongConsecutiveEdgeIsSwitchedOffAndTheTrajectoryComesBack)
{
  // Every setting of config/default.ini, and its kernel schedule changed to the others: the
  // wrong edge is switched off, alone, and every node comes back within 0.05 m. With the fixed
  // kernel (the default) that takes the whole-graph optimization's second look: from the
  // chain's guess, where the loops are some 180 standard deviations off and the wrong edge
  // fits, the fixed kernel alone keeps the chain and switches the three loops off (the last
  // node 7.9 m off; cost 204 against 57 for GNC's result from there).
  const SystemParams params = loadSystemParams(std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini");
  ASSERT_EQ(params.graph_optimizer.kernel_schedule, graph::KernelSchedule::Fixed);
  ASSERT_TRUE(params.graph_optimizer.isRobust(graph::EdgeKind::Consecutive));
  for (const auto schedule : {graph::KernelSchedule::Fixed, graph::KernelSchedule::Gnc, graph::KernelSchedule::Adaptive})
  {
    SCOPED_TRACE(graph::kernelScheduleName(schedule));
    SystemParams p = params;
    p.graph_optimizer.kernel_schedule = schedule;
    const WrongEdgeRun run = wrongConsecutiveEdge(p);
    EXPECT_EQ(run.switched_off, std::vector<size_t>{run.wrong_edge});
    EXPECT_LT(run.worst, 0.05) << "node " << run.worst_node;
  }
}
