#include <swslam/localize/params.h>

namespace swslam::localize
{
const common::ParamTable<LocalizationParams>& LocalizationParams::table()
{
  using P = LocalizationParams;
  using common::atLeast, common::between, common::above;
  static const auto t =
      common::ParamTable<P>("localization",
                            "Localization on a saved map (swslam-localize): tracking against the map's nodes, "
                            "relocalization by a whole-map search.")
          .real("min_score", &P::min_score, "", between(0, 1),
                "a relocalization's pose scores at least this on the map (mean score of the points)")
          .real("max_second_ratio", &P::max_second_ratio, "", between(0, 1),
                "...and the best pose elsewhere at most this fraction of it (else: ambiguous, wait)")
          .real("ambiguity_radius", &P::ambiguity_radius, "m", above(0), "'elsewhere': farther than this")
          .angle("theta_step_DEG", &P::theta_step, between(0.1, 10), "rotation step of the whole-map search")
          .real("min_inlier_fraction", &P::min_inlier_fraction, "", between(0, 1),
                "a tracked match explains at least this fraction of the scan's rays")
          .real("lost_after", &P::lost_after, "s", atLeast(0), "placed by the prediction this long: lost")
          .real("relocalize_interval", &P::relocalize_interval, "s", atLeast(0),
                "log time between two whole-map searches while lost");
  return t;
}

}  // namespace swslam::localize
