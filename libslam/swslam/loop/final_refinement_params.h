#pragma once
// Parameters of the final refinement pass (doc/loop-closure.md), section [final_refinement].

#include <mrpt/config/CLoadableOptions.h>

#include <cmath>

namespace swslam::loop
{
struct FinalRefinementParams : public mrpt::config::CLoadableOptions
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
  double sigma_theta = 1.0 * M_PI / 180;  ///< [rad] (ini: sigma_theta_DEG)
  double max_correction_xy = 0.3;    ///< [m] the match may move the graph's guess at most this...
  double max_correction_theta = 5.0 * M_PI / 180;  ///< [rad] ...and turn it at most this (ini: _DEG)

  /** Throws std::invalid_argument naming the first out-of-range parameter. */
  void check() const;

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

}  // namespace swslam::loop
