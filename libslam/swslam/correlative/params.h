#pragma once
// Parameters of the correlative search, section [correlative] (doc/tracking.md,
// doc/loop-closure.md): tracking searches when its prediction failed, a loop check when its
// match from the graph's guess failed.

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>

namespace swslam::correlative
{
/** Section [correlative]: declared in table() (params.cpp). */
struct CorrelativeParams
{
  bool enabled = true;  ///< false: neither tracking nor loop checks ever search
  double resolution = 0.1;  ///< [m] score grid cell, and translation step
  double sigma = 0.1;       ///< [m] score kernel: exp(-d^2 / 2 sigma^2)
  double free_space_score = -1.0;  ///< in [-1, 0]: score of a point where the keyframes saw free space
  double window_xy = 3.0;   ///< [m] translations within +- this of the prediction
  double window_theta = mrpt::DEG2RAD(180.0);  ///< [rad] rotations within +- this
  double theta_step = mrpt::DEG2RAD(1.0);  ///< [rad] rotation step
  double cost_per_m = 0.02;    ///< motion prior: objective = score - cost_per_m |t - t_pred| ...
  double cost_per_rad = 0.1;  ///< ... - cost_per_rad |theta - theta_pred|
  double max_range = 30.0;  ///< [m] farther points are left out of the grid and the search
  double min_score = 0.1;   ///< a search result scores at least this (mean cell value, 0..1)

  static const common::ParamTable<CorrelativeParams>& table();
};

}  // namespace swslam::correlative
