#pragma once
// A search's inputs from the [correlative] parameters: the score pyramid of reference rays,
// deep enough for the window, and the window around a guess. Tracking and loop checks search
// with them; the search itself (search.h) takes plain values.

#include <swslam/correlative/params.h>
#include <swslam/correlative/score_grid.h>
#include <swslam/correlative/search.h>
#include <swslam/sensor/scan.h>

#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace swslam::correlative
{
/** The score pyramid of reference rays (in the reference sensor frame), deep enough for the
 * search window: the kernels of their hits, and free_space_score on the cells they cross. The
 * caller leaves out rays longer than max_range. Throws std::length_error if the pyramid would
 * hold more than kMaxPyramidCells cells (rays spread too far: a sensor pose far out). */
ScorePyramid searchPyramid(const std::vector<Ray>& reference, const CorrelativeParams& p);

/** The search window of the parameters (window_xy, window_theta, theta_step, motion prior)
 * centred on `guess` (a sensor pose in the reference sensor frame). */
SearchWindow searchWindow(const CorrelativeParams& p, const mrpt::poses::CPose2D& guess);

/** The rays of one scan seen from its own sensor (origin 0), up to max_range: the reference
 * of a search against that scan alone. */
std::vector<Ray> scanRays(const sensor::Scan& scan, double max_range);

}  // namespace swslam::correlative
