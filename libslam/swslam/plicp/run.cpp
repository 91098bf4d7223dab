#include <swslam/plicp/run.h>

#include <swslam/plicp/closed_form.h>
#include <swslam/plicp/outliers.h>

#include <algorithm>
#include <cmath>

namespace swslam::plicp
{
void transformInto(const sensor::Scan& s, const Eigen::Vector3d& x, std::vector<Eigen::Vector2d>& out)
{
  const double c = std::cos(x.z()), sn = std::sin(x.z());
  out.resize(s.size());
  for (size_t i = 0; i < s.size(); i++)
  {
    const auto& p = s.points[i];
    out[i] = {c * p.x() - sn * p.y() + x.x(), sn * p.x() + c * p.y() + x.y()};
  }
}

std::vector<Eigen::Vector2d> transformed(const sensor::Scan& s, const Eigen::Vector3d& x)
{
  std::vector<Eigen::Vector2d> out;
  transformInto(s, x, out);
  return out;
}

std::vector<double> lineErrors(const sensor::Scan& ref, const std::vector<Eigen::Vector2d>& cur_in_ref,
                               const std::vector<Correspondence>& cs)
{
  std::vector<double> e(cs.size());
  for (size_t k = 0; k < cs.size(); k++)
    e[k] = std::abs(segmentNormal(ref.points[cs[k].j1], ref.points[cs[k].j2])
                        .dot(cur_in_ref[cs[k].i] - ref.points[cs[k].j1]));
  return e;
}

void lineErrorsInto(const ReferenceScan& reference, const std::vector<Eigen::Vector2d>& cur_in_ref,
                    const std::vector<Correspondence>& cs, std::vector<double>& out)
{
  const sensor::Scan& ref = reference.scan;
  out.resize(cs.size());
  for (size_t k = 0; k < cs.size(); k++)
    out[k] = std::abs(correspondenceNormal(ref, reference.index, cs[k])
                          .dot(cur_in_ref[cs[k].i] - ref.points[cs[k].j1]));
}

std::vector<double> lineErrors(const ReferenceScan& reference,
                               const std::vector<Eigen::Vector2d>& cur_in_ref,
                               const std::vector<Correspondence>& cs)
{
  std::vector<double> e;
  lineErrorsInto(reference, cur_in_ref, cs, e);
  return e;
}

namespace
{
/** Outlier rejection of the correspondences found within `radius` (doubles only at the final
 * radius: while the scans are still far apart many points share a nearest neighbour, and
 * thinning them then shrinks the basin of convergence). */
std::vector<Correspondence> rejectOutliers(const ReferenceScan& reference,
                                           const std::vector<Eigen::Vector2d>& cur_in_ref,
                                           std::vector<Correspondence> found, double radius,
                                           const PlicpParams& params, bool early = false)
{
  if (params.remove_doubles && radius <= params.max_correspondence_dist)
  {
    if (early)
      keepNearPerReference(found, static_cast<int>(reference.scan.size()), params.early_doubles_ratio);
    else
      keepNearestPerReference(found, static_cast<int>(reference.scan.size()));
  }
  thread_local std::vector<double> errors;  // per-thread buffer: no allocation per call
  lineErrorsInto(reference, cur_in_ref, found, errors);
  trimByError(found, errors, params.trim_keep_fraction, params.adaptive_quantile, params.adaptive_mult);
  return found;
}

/** Convergence test of a step: the epsilons at the final radius; at a coarse radius or in the
 * tolerant stage only settling is needed (2% of the radius, 0.3 deg), the fine stages refine it. */
bool isSmallStep(const Eigen::Vector3d& step, double radius, const PlicpParams& params, bool early)
{
  const bool coarse = radius > params.max_correspondence_dist || early;
  // (the settling test of a coarse radius applies at the final radius too: 2% of it)
  const double eps_xy = coarse ? 0.02 * radius : params.epsilon_xy;
  const double eps_th = coarse ? 0.005 : params.epsilon_theta;
  return step.head<2>().norm() < eps_xy && std::abs(step.z()) < eps_th;
}

/** Iterates from run.x with matching radius `radius`, halving it each time the estimate
 * settles, until it settles at max_correspondence_dist (Converged) or max_iterations. Fails
 * with TooFewCorrespondences or Diverged (run.message says why). `first`, if not empty, is
 * the correspondence set at run.x and `radius`, already searched. `memory`: what the searches
 * of this run proved so far (points that moved little are not searched again). */
void iterate(const ReferenceScan& reference, const sensor::Scan& cur, double radius,
             const PlicpParams& params, IcpRun& run, std::vector<Correspondence> first,
             SearchMemory& memory)
{
  const sensor::Scan& ref = reference.scan;
  const size_t min_n = static_cast<size_t>(params.min_correspondences);
  std::vector<Correspondence> previous, before_previous;
  std::vector<Eigen::Vector2d> cur_in_ref;  // buffers reused over the iterations
  std::vector<PointToLine> terms;
  // A poor guess gets a tolerant first stage (early_doubles_ratio): the first iteration, with
  // one match per reference point, finds too few matches or takes a step that the coarse test
  // does not call small. The stage lasts until the estimate first settles; a good guess never
  // enters it (its results are those of the one-to-one rule). A settled stage or radius starts
  // the next one with no set history.
  bool probing = params.early_doubles_ratio > 0 && radius <= params.max_correspondence_dist;
  bool early = false;
  std::vector<Correspondence> probe_set;
  auto settled = [&]() {
    if (radius <= params.max_correspondence_dist && !early) return true;
    if (radius <= params.max_correspondence_dist)
      early = false;
    else
      radius = std::max(params.max_correspondence_dist, 0.5 * radius);
    previous.clear();
    before_previous.clear();
    return false;
  };
  while (run.iterations < params.max_iterations)
  {
    run.iterations++;
    transformInto(cur, run.x, cur_in_ref);
    auto found = run.iterations == 1 && !first.empty()
                     ? std::move(first)
                     : findCorrespondences(ref, reference.index, cur_in_ref, radius, memory);
    if (probing) probe_set = found;
    run.kept = rejectOutliers(reference, cur_in_ref, std::move(found), radius, params, early);
    if (run.kept.size() < min_n && probing)
    {
      probing = false;
      early = true;
      run.kept = rejectOutliers(reference, cur_in_ref, std::move(probe_set), radius, params, early);
    }
    if (run.kept.size() < min_n)
    {
      run.status = MatchStatus::TooFewCorrespondences;
      run.message = std::to_string(run.kept.size()) + " valid correspondences at iteration " +
                    std::to_string(run.iterations) + " (need " + std::to_string(min_n) + ")";
      return;
    }
    // The same set gives the same solution: a fixed point (or a 2-cycle between two sets).
    if ((run.kept == previous || run.kept == before_previous) && settled())
    {
      run.status = MatchStatus::Converged;
      return;
    }
    terms.clear();
    for (const auto& k : run.kept)
      terms.push_back({cur.points[k.i], ref.points[k.j1], correspondenceNormal(ref, reference.index, k)});
    const auto next = solvePointToLine(terms, run.x);
    if (!next || !next->allFinite())
    {
      run.status = MatchStatus::Diverged;
      run.message = "closed-form step failed at iteration " + std::to_string(run.iterations);
      return;
    }
    const Eigen::Vector3d step(next->x() - run.x.x(), next->y() - run.x.y(),
                               std::remainder(next->z() - run.x.z(), 2 * M_PI));
    run.x = *next;
    if (probing)
    {
      probing = false;
      early = !isSmallStep(step, radius, params, /*coarse=*/true);
    }
    std::swap(before_previous, previous);
    previous = run.kept;  // reuses before_previous's old storage
    if (isSmallStep(step, radius, params, early) && settled())
    {
      run.status = MatchStatus::Converged;
      return;
    }
  }
  run.status = MatchStatus::MaxIterations;
}

/** Coarse to fine: when the guess matches few points within the final radius, a wide radius
 * first widens the basin of convergence (it halves each time the estimate settles). Returns
 * the start radius; `probe` gets the correspondences at the final radius if they were searched
 * and the start is fine. The probe's search goes into `memory`, which the iterations reuse. */
double startRadius(const ReferenceScan& reference, const sensor::Scan& cur, const Eigen::Vector3d& x,
                   const PlicpParams& params, std::vector<Correspondence>& probe,
                   SearchMemory& memory)
{
  const double fine = params.max_correspondence_dist;
  if (params.initial_correspondence_dist <= fine) return fine;
  probe = findCorrespondences(reference.scan, reference.index, transformed(cur, x), fine, memory);
  if (probe.size() >= params.coarse_start_fraction * cur.size()) return fine;
  probe.clear();
  return params.initial_correspondence_dist;
}

/** A full run (start radius, then iterations) from `start`. */
IcpRun runFrom(const ReferenceScan& reference, const sensor::Scan& cur, const Eigen::Vector3d& start,
               const PlicpParams& params)
{
  IcpRun run;
  run.x = start;
  std::vector<Correspondence> probe;
  SearchMemory memory;
  const double radius = startRadius(reference, cur, start, params, probe, memory);
  iterate(reference, cur, radius, params, run, std::move(probe), memory);
  return run;
}

/** Quality of a run's end: current points within 3 range sigmas of the reference surface
 * (0 for a failed run). Unlike the raw overlap, a wrong local minimum scores low. */
size_t inlierCount(const ReferenceScan& reference, const sensor::Scan& cur, const IcpRun& run,
                   const PlicpParams& params, bool kept_only = false)
{
  if (run.status == MatchStatus::TooFewCorrespondences || run.status == MatchStatus::Diverged)
    return 0;
  const auto pts = transformed(cur, run.x);
  const auto errors =
      lineErrors(reference, pts,
                 kept_only ? run.kept
                           : findCorrespondences(reference.scan, reference.index, pts,
                                                 params.max_correspondence_dist));
  return static_cast<size_t>(std::count_if(errors.begin(), errors.end(), [&](double e) {
    return e < 3 * params.range_sigma;
  }));
}
/** PLICP from the guess; if it ends poorly (few inliers), also from the guess turned by
 * +-1..retry_rotations steps, keeping a retry only if it has retry_min_gain times the
 * inliers of the first run (a low-overlap pair must not be "improved" into a wrong pose). */
}  // namespace

bool fullResolutionStep(const ReferenceScan& reference, const sensor::Scan& cur,
                        const PlicpParams& params, IcpRun& run)
{
  const sensor::Scan& ref = reference.scan;
  const auto cur_in_ref = transformed(cur, run.x);
  auto kept = rejectOutliers(reference, cur_in_ref,
                             findCorrespondences(ref, reference.index, cur_in_ref,
                                                 params.max_correspondence_dist),
                             params.max_correspondence_dist, params);
  if (kept.size() < static_cast<size_t>(params.min_correspondences)) return false;
  std::vector<PointToLine> terms;
  terms.reserve(kept.size());
  for (const auto& k : kept) terms.push_back({cur.points[k.i], ref.points[k.j1], correspondenceNormal(ref, reference.index, k)});
  const auto next = solvePointToLine(terms, run.x);
  if (!next || !next->allFinite()) return false;
  run.x = *next;
  run.kept = std::move(kept);
  run.iterations++;
  return true;
}

IcpRun runWithRetries(const ReferenceScan& reference, const sensor::Scan& cur, const Eigen::Vector3d& x0,
                      const PlicpParams& params)
{
  IcpRun run = runFrom(reference, cur, x0, params);
  // The run's own final set counts no more inliers than a fresh search, so enough of them
  // settles it without one (the common case, kept off the per-scan hot path).
  const double enough = params.retry_below_inlier_fraction * cur.size();
  if (enough <= 0) return run;  // retries off: no inlier count needed
  if (inlierCount(reference, cur, run, params, /*kept_only=*/true) >= enough) return run;
  const size_t first = inlierCount(reference, cur, run, params);
  if (first >= enough) return run;
  size_t best = first;
  int iterations = run.iterations;
  for (int h = 1; h <= 2 * params.retry_rotations; h++)
  {
    const int k = (h + 1) / 2 * (h % 2 ? 1 : -1);  // +1, -1, +2, -2, ...
    IcpRun trial = runFrom(reference, cur, x0 + Eigen::Vector3d(0, 0, k * params.retry_rotation_step), params);
    iterations += trial.iterations;
    const size_t n = inlierCount(reference, cur, trial, params);
    if (n > best && n >= params.retry_min_gain * first)
    {
      best = n;
      run = std::move(trial);
    }
  }
  run.iterations = iterations;
  return run;
}

}  // namespace swslam::plicp
