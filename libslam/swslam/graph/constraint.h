#pragma once
// A measured constraint between two graph nodes, as tracking and loop closure make them.

#include <swslam/graph/edge_kind.h>

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

namespace swslam::graph
{
/** A constraint for the graph: the vehicle pose of node `to` seen from node `from`. */
struct Constraint
{
  size_t from = 0, to = 0;
  mrpt::poses::CPose2D z;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
  EdgeKind kind = EdgeKind::Consecutive;
};

}  // namespace swslam::graph
