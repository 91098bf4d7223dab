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
          .real("resolution", &P::resolution, "m", common::aboveUpTo(0, 10), "score grid cell, and translation step")
          .real("sigma", &P::sigma, "m", above(0), "score of a point: exp(-d^2 / 2 sigma^2), d to the nearest keyframe point")
          .real("free_space_score", &P::free_space_score, "", between(-1, 0),
                "score of a point in space the keyframes' rays crossed")
          .angle("theta_step_DEG", &P::theta_step, between(0.1, 360), "rotation step of the search")
          .real("cost_per_m", &P::cost_per_m, "", atLeast(0), "motion prior: score lost per metre from the prediction...")
          .real("cost_per_rad", &P::cost_per_rad, "", atLeast(0), "...and per radian")
          .real("min_score", &P::min_score, "", between(0, 1), "a search result scores at least this (mean score of the points)")
          // Each point's kernel covers (2 ceil(3 sigma / resolution) + 1)^2 cells of the score grid.
          .rule([](const P& p) { return p.sigma <= 10 * p.resolution; }, "sigma must be at most 10 resolution")
          // The pyramid (padded by the window) and the rotated lattices stay in memory.
          .rule([](const P& p) { return p.window_xy <= 256 * p.resolution; }, "window_xy must be at most 256 resolution");
  return t;
}

}  // namespace swslam::correlative
