#include <swslam/loop/final_refinement_params.h>

namespace swslam::loop
{
const common::ParamTable<FinalRefinementParams>& FinalRefinementParams::table()
{
  using P = FinalRefinementParams;
  using common::above, common::atLeast, common::between;
  static const auto t =
      common::ParamTable<P>("final_refinement",
                            "Once the input ends: every pair of close nodes without an edge matched by PLICP, then the "
                            "whole graph optimized again.")
          .flag("enabled", &P::enabled, "run the pass")
          .integer("passes", &P::passes, "", atLeast(1), "rounds of (match the pairs, add the accepted edges, optimize)")
          .real("radius", &P::radius, "m", atLeast(0), "pairs at most this far apart at their optimized poses")
          .integer("max_pairs_per_node", &P::max_pairs_per_node, "", atLeast(0),
                   "each node is matched with at most this many older ones, nearest first (0: all)")
          .real("min_inlier_fraction", &P::min_inlier_fraction, "", between(0, 1),
                "a converged match must pair at least this fraction of the newer scan's valid rays")
          .real("chi2_gate", &P::chi2_gate, "", above(0), "bound on d2 = e' S^-1 e, as for a loop check")
          .real("sigma_xy", &P::sigma_xy, "m", above(0), "position std of the optimized graph's relative pose")
          .angle("sigma_theta_DEG", &P::sigma_theta, above(0), "heading std of the optimized graph's relative pose")
          .real("max_correction_xy", &P::max_correction_xy, "m", atLeast(0), "the match may move the graph's guess at most this...")
          .angle("max_correction_theta_DEG", &P::max_correction_theta, atLeast(0), "...and turn it at most this");
  return t;
}

}  // namespace swslam::loop
