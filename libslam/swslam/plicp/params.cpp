#include <swslam/plicp/params.h>

namespace swslam::plicp
{
const common::ParamTable<PlicpParams>& PlicpParams::table()
{
  using P = PlicpParams;
  using common::Tier;
  static const auto t =
      common::ParamTable<P>("plicp", "Point-to-line ICP (paper sec. II.A) and its closed-form covariance (sec. II.B).")
          .real("range_sigma", &P::range_sigma, "m", common::above(0), "range noise std (datasheet), for the covariance",
                Tier::User)
          // A match that never settles runs to the cap, on every scan: bounded so that a run cannot stall.
          .integer("max_iterations", &P::max_iterations, "", common::between(1, 1000), "iteration cap")
          .real("epsilon_xy", &P::epsilon_xy, "m", common::above(0), "converged when a step moves less than this...")
          .angle("epsilon_theta_DEG", &P::epsilon_theta, common::above(0), "...and turns less than this")
          .real("max_correspondence_dist", &P::max_correspondence_dist, "m", common::above(0),
                "farther point pairs are not matched")
          .real("min_segment_length", &P::min_segment_length, "m", common::atLeast(0),
                "shortest reference segment j1-j2 that defines a normal")
          .flag("remove_doubles", &P::remove_doubles, "keep only the nearest of several points matched to one reference point")
          .real("trim_keep_fraction", &P::trim_keep_fraction, "", common::aboveUpTo(0, 1),
                "keep at most this fraction of the best matches...")
          .real("adaptive_quantile", &P::adaptive_quantile, "", common::aboveUpTo(0, 1),
                "...and drop errors above adaptive_mult x this quantile")
          .real("adaptive_mult", &P::adaptive_mult, "", common::above(0), "see adaptive_quantile")
          .integer("min_correspondences", &P::min_correspondences, "", common::atLeast(3),
                   "fewer valid correspondences: the match fails")
          .real("max_correction_xy", &P::max_correction_xy, "m", common::above(0),
                "a result farther than this from the guess is diverged...")
          .angle("max_correction_theta_DEG", &P::max_correction_theta, common::above(0), "...or turned more than this")
          .flag("covariance_from_residuals", &P::covariance_from_residuals,
                "scale the covariance by the noise the residuals show, sum r^2 / (n - 3) / range_sigma^2, when above 1");
  return t;
}

}  // namespace swslam::plicp
