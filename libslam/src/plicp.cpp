#include "swslam/plicp/plicp.h"

#include "swslam/plicp/closed_form.h"
#include "swslam/plicp/covariance.h"
#include "swslam/plicp/outliers.h"

#include <cmath>

namespace swslam
{
using plicp::Correspondence;

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
std::vector<Eigen::Vector2d> transformed(const Scan& s, const Eigen::Vector3d& x)
{
  const double c = std::cos(x.z()), sn = std::sin(x.z());
  std::vector<Eigen::Vector2d> out(s.size());
  for (size_t i = 0; i < s.size(); i++)
  {
    const auto& p = s.points[i];
    out[i] = {c * p.x() - sn * p.y() + x.x(), sn * p.x() + c * p.y() + x.y()};
  }
  return out;
}

Eigen::Vector2d normalOf(const Scan& ref, const Correspondence& k)
{
  const Eigen::Vector2d e = (ref.points[k.j1] - ref.points[k.j2]).normalized();
  return {-e.y(), e.x()};
}

/** Point-to-line distance of each correspondence (eq. 1's residual). */
std::vector<double> lineErrors(const Scan& ref, const std::vector<Eigen::Vector2d>& cur_in_ref,
                               const std::vector<Correspondence>& cs)
{
  std::vector<double> e(cs.size());
  for (size_t k = 0; k < cs.size(); k++)
    e[k] = std::abs(normalOf(ref, cs[k]).dot(cur_in_ref[cs[k].i] - ref.points[cs[k].j1]));
  return e;
}

std::string sensorMismatch(const Scan& a, const Scan& b)
{
  if (a.sensor_label == b.sensor_label && a.beam_count == b.beam_count &&
      std::abs(a.aperture - b.aperture) < 1e-6 && (a.sensor_pose - b.sensor_pose).norm() < 1e-9)
    return {};
  auto describe = [](const Scan& s) {
    return "'" + s.sensor_label + "' (" + std::to_string(s.beam_count) + " beams, " +
           std::to_string(s.aperture * 180 / M_PI) + " deg)";
  };
  return "reference and current scans come from different sensors: " + describe(a) + " vs " +
         describe(b);
}

/** Outlier rejection of the correspondences found within `radius` (doubles only at the final
 * radius: while the scans are still far apart many points share a nearest neighbour, and
 * thinning them then shrinks the basin of convergence). */
std::vector<Correspondence> rejectOutliers(const Scan& ref,
                                           const std::vector<Eigen::Vector2d>& cur_in_ref,
                                           std::vector<Correspondence> found, double radius,
                                           const PlicpParams& params)
{
  if (params.remove_doubles && radius <= params.max_correspondence_dist)
    found = plicp::keepNearestPerReference(found, static_cast<int>(ref.size()));
  return plicp::trimByError(found, lineErrors(ref, cur_in_ref, found), params.trim_keep_fraction,
                            params.adaptive_quantile, params.adaptive_mult);
}

/** Convergence test of a step: the epsilons at the final radius; at a coarse radius only
 * settling is needed (2% of the radius, 0.3 deg), the fine stages refine it. */
bool isSmallStep(const Eigen::Vector3d& step, double radius, const PlicpParams& params)
{
  const bool coarse = radius > params.max_correspondence_dist;
  const double eps_xy = coarse ? 0.02 * radius : params.epsilon_xy;
  const double eps_th = coarse ? 0.005 : params.epsilon_theta;
  return step.head<2>().norm() < eps_xy && std::abs(step.z()) < eps_th;
}

MatchResult fail(MatchResult r, MatchStatus s, std::string msg)
{
  r.status = s;
  r.message = std::move(msg);
  return r;
}
}  // namespace

MatchResult matchScans(const ReferenceScan& reference, const Scan& cur,
                       const mrpt::poses::CPose2D& initial_guess, const PlicpParams& params)
{
  const Scan& ref = reference.scan;
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
  Eigen::Vector3d x = x0;
  const double fine = params.max_correspondence_dist;
  // Coarse to fine: when the guess matches few points within the final radius, a wide radius
  // first widens the basin of convergence; it halves each time the estimate settles.
  auto search = [&](const std::vector<Eigen::Vector2d>& pts, double radius) {
    return plicp::findCorrespondences(ref, reference.index, pts, radius);
  };
  double radius = fine;
  auto cur_in_ref = transformed(cur, x);
  auto found = search(cur_in_ref, fine);  // also the first iteration's set if no coarse start
  if (params.initial_correspondence_dist > fine &&
      found.size() < params.coarse_start_fraction * cur.size())
  {
    radius = params.initial_correspondence_dist;
    found = search(cur_in_ref, radius);
  }
  std::vector<Correspondence> kept, previous, before_previous;
  auto settled = [&]() {
    if (radius <= fine) return true;
    radius = std::max(fine, 0.5 * radius);
    previous.clear();
    before_previous.clear();
    return false;
  };
  res.status = MatchStatus::MaxIterations;
  for (int it = 1; it <= params.max_iterations; it++)
  {
    res.iterations = it;
    if (it > 1)
    {
      cur_in_ref = transformed(cur, x);
      found = search(cur_in_ref, radius);
    }
    kept = rejectOutliers(ref, cur_in_ref, std::move(found), radius, params);
    if (kept.size() < min_n)
      return fail(res, MatchStatus::TooFewCorrespondences,
                  std::to_string(kept.size()) + " valid correspondences at iteration " +
                      std::to_string(it) + " (need " + std::to_string(min_n) + ")");
    // The same set gives the same solution: a fixed point (or a 2-cycle between two sets).
    if ((kept == previous || kept == before_previous) && settled())
    {
      res.status = MatchStatus::Converged;
      break;
    }
    std::vector<plicp::PointToLine> terms;
    terms.reserve(kept.size());
    for (const auto& k : kept) terms.push_back({cur.points[k.i], ref.points[k.j1], normalOf(ref, k)});
    const auto next = plicp::solvePointToLine(terms, x);
    if (!next || !next->allFinite())
      return fail(res, MatchStatus::Diverged, "closed-form step failed at iteration " + std::to_string(it));
    const Eigen::Vector3d step(next->x() - x.x(), next->y() - x.y(),
                               std::remainder(next->z() - x.z(), 2 * M_PI));
    x = *next;
    before_previous = std::move(previous);
    previous = kept;
    if (isSmallStep(step, radius, params) && settled())
    {
      res.status = MatchStatus::Converged;
      break;
    }
  }
  res.pose = mrpt::poses::CPose2D(x.x(), x.y(), x.z());
  if ((x.head<2>() - x0.head<2>()).norm() > params.max_correction_xy ||
      std::abs(std::remainder(x.z() - x0.z(), 2 * M_PI)) > params.max_correction_theta)
    return fail(res, MatchStatus::Diverged, "result moved beyond max_correction from the guess");

  // Residuals and covariance (eq. 4-10) at the final estimate.
  cur_in_ref = transformed(cur, x);
  const auto errors = lineErrors(ref, cur_in_ref, kept);
  res.correspondences = kept.size();
  res.sum_sq_residuals = 0;
  for (double e : errors) res.sum_sq_residuals += e * e;
  std::vector<plicp::CovarianceTerm> cov_terms;
  cov_terms.reserve(kept.size());
  for (const auto& k : kept)
  {
    auto dir = [](const Scan& s, int j) { return Eigen::Vector2d(s.points[j] / s.ranges[j]); };
    cov_terms.push_back({dir(cur, k.i), dir(ref, k.j1), dir(ref, k.j2), cur.ranges[k.i],
                         ref.ranges[k.j1], ref.ranges[k.j2], k.i, k.j1, k.j2});
  }
  res.covariance = plicp::plicpCovariance(cov_terms, x, params.range_sigma);
  return res;
}

}  // namespace swslam
