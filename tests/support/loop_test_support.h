#pragma once
// Helpers shared by the loop-closure and final-refinement tests: graph nodes whose scans are
// simulated on a test world from a mounted sensor, and a weak edge for graph topology.

#include <swslam/loop/closer.h>

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

#include <Eigen/Core>
#include <memory>
#include <random>

#include "test_support.h"

namespace swslam::test
{
/** A loop node `id` at `vehicle`: its scan (541 rays over 270 deg, 30 m, 2 cm noise) taken
 * from the sensor mounted at `mount` on the vehicle. */
inline loop::LoopNode mountedNode(const World& world, size_t id, const mrpt::poses::CPose2D& vehicle,
                            double path_length, std::mt19937& rng,
                            const mrpt::poses::CPose2D& mount)
{
  auto obs = simulateObservation(world, vehicle + mount, 541, 1.5 * M_PI, 30, 0.02, rng);
  obs.sensorPose = mrpt::poses::CPose3D(mount);
  return {id, std::make_shared<const plicp::ReferenceScan>(sensor::scanFromObservation(obs)), path_length};
}

/** An edge with identity information: topology only. */
inline mrpt::poses::CPosePDFGaussianInf weakEdge(const mrpt::poses::CPose2D& z)
{
  return {z, mrpt::math::CMatrixDouble33(Eigen::Matrix3d::Identity())};
}

}  // namespace swslam::test
