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
/** Outlier rejection (outliers.h): one match per reference point, then trimming. */
std::vector<Correspondence> rejectOutliers(const ReferenceScan& reference,
                                           const std::vector<Eigen::Vector2d>& cur_in_ref,
                                           std::vector<Correspondence> found, const PlicpParams& params)
{
  if (params.remove_doubles) keepNearestPerReference(found, static_cast<int>(reference.scan.size()));
  thread_local std::vector<double> errors;  // per-thread buffer: no allocation per call
  lineErrorsInto(reference, cur_in_ref, found, errors);
  trimByError(found, errors, params.trim_keep_fraction, params.adaptive_quantile, params.adaptive_mult);
  return found;
}

bool isSmallStep(const Eigen::Vector3d& step, const PlicpParams& params)
{
  return step.head<2>().norm() < params.epsilon_xy && std::abs(step.z()) < params.epsilon_theta;
}
}  // namespace

IcpRun iterate(const ReferenceScan& reference, const sensor::Scan& cur, const Eigen::Vector3d& x0,
               const PlicpParams& params)
{
  const sensor::Scan& ref = reference.scan;
  const size_t min_n = static_cast<size_t>(params.min_correspondences);
  IcpRun run;
  run.x = x0;
  SearchMemory memory;  // what the searches of this run proved so far: points that moved little are not searched again
  std::vector<Correspondence> previous, before_previous;
  std::vector<Eigen::Vector2d> cur_in_ref;  // buffers reused over the iterations
  std::vector<PointToLine> terms;
  while (run.iterations < params.max_iterations)
  {
    run.iterations++;
    transformInto(cur, run.x, cur_in_ref);
    run.kept = rejectOutliers(
        reference, cur_in_ref,
        findCorrespondences(ref, reference.index, cur_in_ref, params.max_correspondence_dist, memory), params);
    if (run.kept.size() < min_n)
    {
      run.status = MatchStatus::TooFewCorrespondences;
      run.message = std::to_string(run.kept.size()) + " valid correspondences at iteration " +
                    std::to_string(run.iterations) + " (need " + std::to_string(min_n) + ")";
      return run;
    }
    // The same set gives the same solution: a fixed point (or a 2-cycle between two sets).
    if (run.kept == previous || run.kept == before_previous)
    {
      run.status = MatchStatus::Converged;
      return run;
    }
    terms.clear();
    for (const auto& k : run.kept)
      terms.push_back({cur.points[k.i], ref.points[k.j1], correspondenceNormal(ref, reference.index, k)});
    const auto next = solvePointToLine(terms, run.x);
    if (!next || !next->allFinite())
    {
      run.status = MatchStatus::Diverged;
      run.message = "closed-form step failed at iteration " + std::to_string(run.iterations);
      return run;
    }
    const Eigen::Vector3d step(next->x() - run.x.x(), next->y() - run.x.y(),
                               std::remainder(next->z() - run.x.z(), 2 * M_PI));
    run.x = *next;
    std::swap(before_previous, previous);
    previous = run.kept;  // reuses before_previous's old storage
    if (isSmallStep(step, params))
    {
      run.status = MatchStatus::Converged;
      return run;
    }
  }
  run.status = MatchStatus::MaxIterations;
  return run;
}

}  // namespace swslam::plicp
