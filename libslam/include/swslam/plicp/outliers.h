#pragma once
// Outlier rejection of PLICP correspondences: one match per reference point, then
// trimming of the worst point-to-line errors (a fixed fraction and an adaptive bound).

#include <swslam/plicp/correspondences.h>

#include <vector>

namespace swslam::plicp
{
/** Keeps, for every reference point j1 matched by several current points, only the match
 * with the smallest point-to-point distance. Order of the survivors is preserved. */
std::vector<Correspondence> keepNearestPerReference(const std::vector<Correspondence>& in,
                                                    int ref_size);

/** Keeps the correspondences whose error is at most min(the keep_fraction quantile,
 * adaptive_mult x the adaptive_quantile quantile) of `errors` (aligned with `in`). */
std::vector<Correspondence> trimByError(const std::vector<Correspondence>& in,
                                        const std::vector<double>& errors, double keep_fraction,
                                        double adaptive_quantile, double adaptive_mult);

/** keepNearestPerReference() in place (no allocation). */
void keepNearestPerReferenceInPlace(std::vector<Correspondence>& cs, int ref_size);

/** trimByError() in place: `cs` and `errors` (aligned) keep only the survivors, in order. */
void trimByErrorInPlace(std::vector<Correspondence>& cs, std::vector<double>& errors,
                        double keep_fraction, double adaptive_quantile, double adaptive_mult);

}  // namespace swslam::plicp
