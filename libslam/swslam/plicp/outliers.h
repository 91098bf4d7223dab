#pragma once
// Outlier rejection of PLICP correspondences: one match per reference point, then
// trimming of the worst point-to-line errors (a fixed fraction and an adaptive bound).

#include <swslam/plicp/correspondences.h>

#include <vector>

namespace swslam::plicp
{
/** Keeps in `cs`, for every reference point j1 matched by several current points, only the
 * match with the smallest point-to-point distance. Order of the survivors is preserved; no
 * allocation. */
void keepNearestPerReference(std::vector<Correspondence>& cs, int ref_size);

/** Keeps the correspondences whose error is at most min(the keep_fraction quantile,
 * adaptive_mult x the adaptive_quantile quantile) of `errors`. `cs` and `errors` (aligned)
 * keep only the survivors, in order. */
void trimByError(std::vector<Correspondence>& cs, std::vector<double>& errors, double keep_fraction,
                 double adaptive_quantile, double adaptive_mult);

}  // namespace swslam::plicp
