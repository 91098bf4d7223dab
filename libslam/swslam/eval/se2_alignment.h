#pragma once
// Best rigid SE(2) alignment of two associated point sets (Umeyama 1991 / Horn 1987,
// restricted to the plane and without scale): the T minimizing sum_i |b_i - T a_i|^2.

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <vector>

namespace swslam::eval
{
/** The rigid transform T with T (+) a_i ~ b_i in the least-squares sense. Throws
 * std::invalid_argument if the sets differ in size or are empty. With a single point (or
 * all points coincident) the rotation is undetermined and returned as 0. */
mrpt::poses::CPose2D alignSE2(const std::vector<Eigen::Vector2d>& a,
                              const std::vector<Eigen::Vector2d>& b);

/** sum_i |b_i - T a_i|^2, the cost alignSE2 minimizes. */
double alignmentCost(const mrpt::poses::CPose2D& T, const std::vector<Eigen::Vector2d>& a,
                     const std::vector<Eigen::Vector2d>& b);

}  // namespace swslam::eval
