#include <swslam/loop/params.h>

namespace swslam::loop
{
const common::ParamTable<LoopClosureParams>& LoopClosureParams::table()
{
  using P = LoopClosureParams;
  using common::Tier;
  using common::above, common::atLeast, common::between;
  static const auto t =
      common::ParamTable<P>("loop_closure",
                            "Loop closure (paper sec. II.C, III.B), verified by PLICP and a chi-square gate.")
          .flag("enabled", &P::enabled, "look for loops at each new node", Tier::User)
          .real("max_distance", &P::max_distance, "m", atLeast(0),
                "a candidate's graph pose is at most this far from the new node's...", Tier::User)
          .real("max_search_radius", &P::max_search_radius, "m", atLeast(0),
                "...or, if none is, 3 drift std over the path between them, up to this (0: never); its search spans as much")
          .integer("min_index_gap", &P::min_index_gap, "", atLeast(1), "...and it is at least this many nodes older")
          .integer("max_candidates", &P::max_candidates, "", atLeast(0), "candidates verified per new node, nearest first")
          .real("min_inlier_fraction", &P::min_inlier_fraction, "", between(0, 1),
                "a converged match must pair at least this fraction of the new scan's valid rays")
          .real("chi2_gate", &P::chi2_gate, "", above(0), "bound on d2 = e' S^-1 e (11.34: 99 % of chi-square with 3 dof)")
          .real("drift_xy_per_m", &P::drift_xy_per_m, "m/m", atLeast(0), "drift position std per metre travelled between the two nodes...")
          .angle("drift_theta_per_m_DEG", &P::drift_theta_per_m, atLeast(0), "...and heading std, per metre")
          .real("min_drift_sigma_xy", &P::min_drift_sigma_xy, "m", above(0), "floor of the drift position std")
          .angle("min_drift_sigma_theta_DEG", &P::min_drift_sigma_theta, above(0), "floor of the drift heading std")
          .integer("consistency_window", &P::consistency_window, "", atLeast(0),
                   "a loop is an edge once another within this many ids agrees with it through the graph (0: at once)")
          .real("ambiguity_radius", &P::ambiguity_radius, "m", atLeast(0),
                "a loop check's search is ambiguous if a pose farther than this from its best (0: no check)...")
          .real("ambiguity_margin", &P::ambiguity_margin, "", atLeast(0), "...has an objective within this of the best's");
  return t;
}

}  // namespace swslam::loop
