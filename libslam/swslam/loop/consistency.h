#pragma once
// Pairwise consistency of loop edges (doc/loop-closure.md): in a self-similar place (a long
// corridor) a single scan match can converge in the wrong place and still pass the overlap
// check and the drift gate, whose bound grows with the path travelled. Two loops found near
// each other (old nodes a, b close in the graph, new nodes n, m close) must then agree: the
// cycle a -> n -> m against a -> b -> m uses two loop edges and two short stretches of the
// graph, which are accurate. A wrong loop rarely agrees with another one. Pure functions.

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

namespace swslam::loop
{
/** One verified loop edge a -> n: vehicle pose of n seen from a, and its covariance. */
struct LoopEdgeMeasure
{
  size_t from = 0, to = 0;
  mrpt::poses::CPose2D z;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
};

/** Cycle error of loops l1 = a -> n and l2 = b -> m given the graph's relative poses
 * rel_ab = x_a^-1 (+) x_b and rel_nm = x_n^-1 (+) x_m:
 * e = (z1 (+) rel_nm)^-1 (+) (rel_ab (+) z2), [x, y, wrapped theta] (zero when consistent). */
Eigen::Vector3d loopPairError(const mrpt::poses::CPose2D& z1, const mrpt::poses::CPose2D& z2,
                              const mrpt::poses::CPose2D& rel_ab, const mrpt::poses::CPose2D& rel_nm);

/** e' S^-1 e for the cycle error, with the conservative, frame-free covariance
 * S = diag(v_xy, v_xy, v_th): v_xy = the largest eigenvalues of both loops' position
 * covariances plus local_sigma_xy^2, v_th = both heading variances plus local_sigma_theta^2
 * (local_*: the error of the two short graph stretches). */
double loopPairChi2(const LoopEdgeMeasure& l1, const LoopEdgeMeasure& l2,
                    const mrpt::poses::CPose2D& rel_ab, const mrpt::poses::CPose2D& rel_nm,
                    double local_sigma_xy, double local_sigma_theta);

}  // namespace swslam::loop
