#include <swslam/plicp/plicp.h>

#include <swslam/plicp/closed_form.h>
#include <swslam/plicp/covariance.h>
#include <swslam/plicp/outliers.h>
#include <swslam/plicp/run.h>

#include <algorithm>
#include <cmath>

namespace swslam::plicp
{
const char* toString(MatchStatus s)
{
  switch (s)
  {
    case MatchStatus::Converged: return "converged";
    case MatchStatus::MaxIterations: return "max_iterations";
    case MatchStatus::TooFewCorrespondences: return "too_few_correspondences";
    case MatchStatus::Diverged: return "diverged";
    case MatchStatus::InvalidInput: return "invalid_input";
  }
  return "unknown";
}

namespace
{
std::string sensorMismatch(const sensor::Scan& a, const sensor::Scan& b)
{
  if (a.sensor_label == b.sensor_label && a.beam_count == b.beam_count &&
      std::abs(a.aperture - b.aperture) < 1e-6 && (a.sensor_pose - b.sensor_pose).norm() < 1e-9)
    return {};
  auto describe = [](const sensor::Scan& s) {
    return "'" + s.sensor_label + "' (" + std::to_string(s.beam_count) + " beams, " +
           std::to_string(s.aperture * 180 / M_PI) + " deg)";
  };
  return "reference and current scans come from different sensors: " + describe(a) + " vs " +
         describe(b);
}

MatchResult fail(MatchResult r, MatchStatus s, std::string msg)
{
  r.status = s;
  r.message = std::move(msg);
  return r;
}
}  // namespace

MatchResult matchScans(const ReferenceScan& reference, const sensor::Scan& cur,
                       const mrpt::poses::CPose2D& initial_guess, const PlicpParams& params)
{
  const sensor::Scan& ref = reference.scan;
  MatchResult res;
  res.ref_valid_rays = ref.size();
  res.cur_valid_rays = cur.size();
  res.pose = initial_guess;
  if (const auto why = sensorMismatch(ref, cur); !why.empty())
    return fail(res, MatchStatus::InvalidInput, why);
  if (reference.index.min_segment != params.min_segment_length)
    return fail(res, MatchStatus::InvalidInput,
                "reference scan was indexed with another min_segment_length");
  const size_t min_n = static_cast<size_t>(params.min_correspondences);
  if (ref.size() < min_n || cur.size() < min_n)
    return fail(res, MatchStatus::TooFewCorrespondences,
                "too few valid rays: reference " + std::to_string(ref.size()) + ", current " +
                    std::to_string(cur.size()) + " (need " + std::to_string(min_n) + ")");

  const Eigen::Vector3d x0(initial_guess.x(), initial_guess.y(), initial_guess.phi());
  const IcpRun run = iterate(reference, cur, x0, params);
  res.iterations = run.iterations;
  res.status = run.status;
  if (!res.ok()) return fail(res, run.status, run.message);
  const Eigen::Vector3d& x = run.x;
  const auto& kept = run.kept;
  res.pose = mrpt::poses::CPose2D(x.x(), x.y(), x.z());
  if ((x.head<2>() - x0.head<2>()).norm() > params.max_correction_xy ||
      std::abs(std::remainder(x.z() - x0.z(), 2 * M_PI)) > params.max_correction_theta)
    return fail(res, MatchStatus::Diverged, "result moved beyond max_correction from the guess");

  // Residuals and covariance (eq. 4-10) at the final estimate.
  const auto cur_in_ref = transformed(cur, x);
  const auto errors = lineErrors(reference, cur_in_ref, kept);
  res.correspondences = kept.size();
  res.sum_sq_residuals = 0;
  for (double e : errors)
  {
    res.sum_sq_residuals += e * e;
    if (e < 3 * params.range_sigma) res.inliers++;
  }
  std::vector<CovarianceTerm> cov_terms;
  cov_terms.reserve(kept.size());
  for (const auto& k : kept)
  {
    auto dir = [](const sensor::Scan& s, int j) { return Eigen::Vector2d(s.points[j] / s.ranges[j]); };
    cov_terms.push_back({dir(cur, k.i), dir(ref, k.j1), dir(ref, k.j2), cur.ranges[k.i],
                         ref.ranges[k.j1], ref.ranges[k.j2], k.i, k.j1, k.j2});
  }
  res.covariance = plicpCovariance(cov_terms, x, params.range_sigma);
  if (params.covariance_from_residuals)
  {
    res.variance_factor = residualVarianceFactor(res.sum_sq_residuals, kept.size(), params.range_sigma);
    res.covariance *= res.variance_factor;
  }
  return res;
}

}  // namespace swslam::plicp
