#pragma once
// Parameters of the final refinement pass (doc/loop-closure.md), section [final_refinement].

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>


namespace swslam::loop
{
struct FinalRefinementParams
{
  bool enabled = true;   ///< once the input ends, match every close unlinked pair of nodes
  int passes = 1;        ///< rounds of (match the pairs, add the accepted edges, optimize all)
  double radius = 3.0;   ///< [m] pairs whose optimized (vehicle) poses are at most this far apart
  int max_pairs_per_node = 20;  ///< each node is matched with at most this many older ones, nearest first (0: all)

  // Acceptance, as a loop check's (verifyLoop) with the drift model replaced by a fixed error
  // of the optimized graph's relative pose.
  double min_inlier_fraction = 0.3;  ///< of the newer scan's valid rays matched at the end
  double chi2_gate = 11.34;          ///< d^2 bound, 99 % of chi-square with 3 dof
  double sigma_xy = 0.1;             ///< [m] std of the optimized graph's relative position
  double sigma_theta = mrpt::DEG2RAD(1.0);  ///< [rad]
  double max_correction_xy = 0.3;    ///< [m] the match may move the graph's guess at most this...
  double max_correction_theta = mrpt::DEG2RAD(5.0);  ///< [rad] ...and turn it at most this

  static const common::ParamTable<FinalRefinementParams>& table();
};

}  // namespace swslam::loop
