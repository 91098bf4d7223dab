#pragma once
// Decimation of the current scan for PLICP's iterations: every k-th valid ray, k chosen from
// the sensor's beam spacing so that the kept rays are about a given angle apart (dense
// sensors thinned, sparse ones untouched). A full-resolution step ends the match
// (plicp_run.cpp), so the result and its covariance use every ray; if that step fails, the
// match keeps the thinned result and reports the thinned ray count as cur_valid_rays.

#include <swslam/sensor/scan.h>

#include <cstddef>

namespace swslam::plicp
{
/** k = max(1, round(spacing / beam spacing)), beam spacing = aperture / (beam_count - 1);
 * 1 when spacing <= 0 or the geometry is degenerate. */
size_t decimationStride(const sensor::Scan& s, double spacing);

/** Rays 0, k, 2k, ... of the valid rays of `s` (angles, ranges, points, beam_index), with
 * the sensor fields of `s`; `s` itself for k <= 1. */
sensor::Scan decimated(const sensor::Scan& s, size_t k);

}  // namespace swslam::plicp
