#pragma once
// The search's steady-motion prior (doc/tracking.md): while the vehicle moves steadily, the
// constant-motion prediction is as good as the recent steps were alike, and the correlative
// search weighs a pose's distance from it by that spread (a Gaussian prior on top of the
// linear cost_per_m), so a corridor's walls cannot pull a step back by a metre.

#include <swslam/tracking/params.h>

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <deque>
#include <optional>

namespace swslam::tracking
{
class SteadyMotion
{
 public:
  /** Motions remembered; the spread is over the last kHistory - 1 prediction errors. */
  static constexpr size_t kHistory = 6;
  /** Motions whose mean length is the vehicle's current step. */
  static constexpr size_t kStepWindow = 3;
  /** Changes needed before the prior applies. */
  static constexpr size_t kMinChanges = 3;

  /** Appends the vehicle motion between the last two scans (oldest forgotten), and the error
   * of its prediction: motion - predicted in translation, `predicted` being the previous
   * motion when not given (the paper's constant motion; none for the first motion). */
  void add(const mrpt::poses::CPose2D& motion,
           const std::optional<mrpt::poses::CPose2D>& predicted = std::nullopt);

  /** The search's quadratic translation cost, score lost per m^2 from the prediction:
   * steady_prior_cost / sigma^2, sigma^2 = max(mean squared remembered prediction error,
   * steady_sigma_min^2), when at least kMinChanges errors are known and the last kStepWindow motions are steady_min_step long on average;
   * 0 otherwise (starting, stopping, turning on the spot, or steady_prior_cost 0). */
  double costPerM2(const TrackingParams& p) const;

  /** Mean squared translation error of the remembered predictions [m^2], at least
   * `min_variance`; `unknown` while fewer than kMinChanges are known. The variance of the
   * next prediction, for the fusion along a match's weak directions (tracking/ambiguity.h). */
  double predictionVariance(double min_variance, double unknown) const;

 private:
  std::deque<mrpt::poses::CPose2D> motions_;
  std::deque<double> squared_errors_;  ///< of the predictions, translation [m^2]
};

}  // namespace swslam::tracking
