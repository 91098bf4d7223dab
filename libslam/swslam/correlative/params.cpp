#include <swslam/correlative/params.h>

namespace swslam::correlative
{
const common::ParamTable<CorrelativeParams>& CorrelativeParams::table()
{
  using P = CorrelativeParams;
  using common::Tier;
  using common::atLeast, common::between, common::above;
  static const auto t =
      common::ParamTable<P>("correlative",
                            "Correlative search by branch and bound: tracking's when its prediction failed, a loop check's "
                            "when its match failed.")
          .real("window_xy", &P::window_xy, "m", atLeast(0), "translations searched: +- this around the prediction",
                Tier::User)
          .angle("window_theta_DEG", &P::window_theta, between(0, 360),
                 "rotations searched: +- this around the prediction (180: the whole circle)", Tier::User)
          .real("max_range", &P::max_range, "m", above(0), "farther points are left out of the grid and the search",
                Tier::User)
          .flag("enabled", &P::enabled, "search at all (tracking and loop checks)")
          .real("trigger_correction_xy", &P::trigger_correction_xy, "m", atLeast(0),
                "search if the match moved the prediction more than this...")
          .angle("trigger_correction_theta_DEG", &P::trigger_correction_theta, atLeast(0), "...or turned it more than this...")
          .real("trigger_inlier_fraction", &P::trigger_inlier_fraction, "", between(0, 1),
                "...or ended with fewer than this fraction of the points within 3 range_sigma of the keyframe")
          .integer("trust_prediction_after", &P::trust_prediction_after, "", atLeast(0),
                   "...unless it stayed on a prediction the last this many scans confirmed (0: always search)")
          .integer("submap_keyframes", &P::submap_keyframes, "", atLeast(1),
                   "the score grid holds the points of the last this many keyframes")
          .real("resolution", &P::resolution, "m", common::aboveUpTo(0, 10), "score grid cell, and translation step")
          .real("sigma", &P::sigma, "m", above(0), "score of a point: exp(-d^2 / 2 sigma^2), d to the nearest keyframe point")
          .real("free_space_score", &P::free_space_score, "", between(-1, 0),
                "score of a point in space the keyframes' rays crossed")
          .angle("theta_step_DEG", &P::theta_step, between(0.1, 360), "rotation step of the search")
          .real("cost_per_m", &P::cost_per_m, "", atLeast(0), "motion prior: score lost per metre from the prediction...")
          .real("cost_per_rad", &P::cost_per_rad, "", atLeast(0), "...and per radian")
          .real("min_score", &P::min_score, "", between(0, 1), "a search result scores at least this (mean score of the points)")
          .real("min_score_gain", &P::min_score_gain, "", atLeast(0),
                "the searched match replaces the first only with an objective this much higher")
          .real("common_points_fraction", &P::common_points_fraction, "", between(0, 1),
                "compare the two matches on the points that can tell them apart when this fraction can (0: on all)")
          .real("surface_goes_on_ratio", &P::surface_goes_on_ratio, "", atLeast(0),
                "a point unseen at one pose tells nothing if at the other it lies on a surface going on past it")
          .real("refine_correspondence_dist", &P::refine_correspondence_dist, "m", atLeast(0),
                "PLICP radius of a second refinement when the first left the search's basin (0: none)")
          .real("prediction_decides_share", &P::prediction_decides_share, "", between(0, 1),
                "the prediction chooses between two matches where the searched one has under this share of information (0: never)")
          .real("steady_prior_cost", &P::steady_prior_cost, "", atLeast(0),
                "steady-motion prior: score lost at one sigma from the prediction (0: none)")
          .real("steady_sigma_min", &P::steady_sigma_min, "m", above(0), "least sigma of the steady-motion prior")
          .real("steady_min_step", &P::steady_min_step, "m", atLeast(0),
                "the steady-motion prior applies while the last 3 steps average at least this")
          // Each point's kernel covers (2 ceil(3 sigma / resolution) + 1)^2 cells of the score grid.
          .rule([](const P& p) { return p.sigma <= 10 * p.resolution; }, "sigma must be at most 10 resolution")
          // The pyramid (padded by the window) and the rotated lattices stay in memory.
          .rule([](const P& p) { return p.window_xy <= 256 * p.resolution; }, "window_xy must be at most 256 resolution");
  return t;
}

}  // namespace swslam::correlative
