#pragma once
// Parameters of loop closure (paper sec. II.C and III.B), section [loop_closure].

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>


namespace swslam::loop
{
struct LoopClosureParams
{
  bool enabled = true;        ///< false: loopCandidates() returns none
  int min_index_gap = 30;     ///< a candidate is at least this many node ids older
  double max_distance = 5.0;  ///< [m] ...and its graph (vehicle) pose at most this far...
  /** [m] ...or, when none is that near, 3 drift standard deviations over the path between
   * the two, up to this (0: max_distance only); such a far candidate's search spans as much */
  double max_search_radius = 25.0;
  int max_candidates = 3;     ///< verified per new node, nearest first

  // Acceptance of a verified candidate.
  double min_inlier_fraction = 0.3;  ///< of the new scan's valid rays matched at the end
  double chi2_gate = 11.34;          ///< d^2 bound, 99 % of chi-square with 3 dof
  // Drift model of the graph's relative pose: a standard deviation proportional to the
  // distance travelled between the two nodes, floored.
  double drift_xy_per_m = 0.03;                  ///< [m/m] position std per metre travelled
  double drift_theta_per_m = mrpt::DEG2RAD(0.3);  ///< [rad/m]
  double min_drift_sigma_xy = 0.1;               ///< [m] floor of the position std
  double min_drift_sigma_theta = mrpt::DEG2RAD(1.0);  ///< [rad]

  // Corroboration: a verified loop becomes an edge only once another verified loop, its new
  // node and its old node each within this many ids of this loop's, agrees with it through
  // the graph (loopPairChi2 <= chi2_gate, local error from the drift model over the two
  // stretches). 0: a verified loop is an edge at once.
  int consistency_window = 10;
  // Ambiguity of the correlative search of a loop check (verifyLoop with `search`): the best
  // pose farther than ambiguity_radius from the search's best must have an objective at least
  // ambiguity_margin lower, or the search gives no loop (self-similar place).
  double ambiguity_radius = 0.5;  ///< [m] (0: no check)
  double ambiguity_margin = 0.05;

  static const common::ParamTable<LoopClosureParams>& table();
};

}  // namespace swslam::loop
