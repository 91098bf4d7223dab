#include <swslam/tracking/ambiguity.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace swslam::tracking
{
namespace
{
bool positiveFinite(double v) { return std::isfinite(v) && v > 0; }
}  // namespace

double weakRatioThreshold(double noise_variance, double min_segment_length, double factor)
{
  if (!positiveFinite(noise_variance) || !positiveFinite(min_segment_length) || !positiveFinite(factor)) return 0;
  const double tilt2 = 2 * noise_variance / (min_segment_length * min_segment_length);
  return std::min(0.5, factor * tilt2);
}

double residualNoiseVariance(double sum_sq_residuals, size_t n, double fallback)
{
  if (n <= 3) return fallback;
  return sum_sq_residuals / static_cast<double>(n - 3);
}

Ambiguity findWeakDirections(const Eigen::Matrix3d& cov, double length, double threshold)
{
  Ambiguity a;
  a.threshold = threshold;
  const Eigen::DiagonalMatrix<double, 3> S(1, 1, length);
  const Eigen::Matrix3d cu = S * (0.5 * (cov + cov.transpose())) * S;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cu);
  const Eigen::Vector3d mu = es.eigenvalues();  // ascending: the strongest direction first
  if (!cu.allFinite() || es.info() != Eigen::Success || !(mu(0) > 0) || !positiveFinite(length))
  {
    a.weak = 3;
    a.directions = Eigen::Matrix3d::Identity();
    a.ratio = 0;
    return a;
  }
  // Information eigenvalue 1 / mu_k over the largest 1 / mu_0 is mu_0 / mu_k.
  a.ratio = mu(0) / mu(2);
  for (int k = 2; k >= 1; k--)  // the weakest first
    if (mu(0) / mu(k) < threshold) a.directions.col(a.weak++) = es.eigenvectors().col(k);
  return a;
}

FacingNormals facingNormals(const std::vector<Eigen::Vector2d>& points, double min_segment)
{
  const int n = static_cast<int>(points.size());
  FacingNormals out;
  out.lo.assign(points.size(), Eigen::Vector2d::Zero());
  out.hi.assign(points.size(), Eigen::Vector2d::Zero());
  if (!(min_segment > 0)) return out;
  const double min2 = min_segment * min_segment;
  const double max2 = kFacingMaxSegmentFactor * kFacingMaxSegmentFactor * min2;
  for (int i = 0; i < n; i++)
    for (const int step : {-1, 1})
    {
      for (int s = 1, k = i + step; s <= kFacingMaxWalk && k >= 0 && k < n; s++, k += step)
      {
        if ((points[k] - points[k - step]).squaredNorm() > max2) break;  // a gap: another surface
        const Eigen::Vector2d chord = points[k] - points[i];
        const double d2 = chord.squaredNorm();
        if (d2 > max2) break;
        if (d2 < min2) continue;
        const Eigen::Vector2d e = chord / std::sqrt(d2);
        (step < 0 ? out.lo : out.hi)[i] = Eigen::Vector2d(-e.y(), e.x());
        break;
      }
    }
  return out;
}

size_t raysFacing(const FacingView& scan, const Eigen::Vector3d& v, double length, size_t enough)
{
  const size_t n = scan.points.size();
  if (!(length > 0) || scan.normals.lo.size() != n || scan.normals.hi.size() != n) return 0;
  // The direction in the scan's own frame: a normal turned by the heading dotted with v is the
  // normal dotted with v turned back; the rotation term does not depend on the frame.
  const double c = std::cos(scan.heading), s = std::sin(scan.heading);
  const Eigen::Vector3d w(c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z());
  size_t facing = 0;
  for (size_t i = 0; i < n && facing < enough; i++)
  {
    const Eigen::Vector2d& q = scan.points[i];
    for (const Eigen::Vector2d* normal : {&scan.normals.lo[i], &scan.normals.hi[i]})
    {
      const Eigen::Vector3d row(normal->x(), normal->y(), (normal->y() * q.x() - normal->x() * q.y()) / length);
      if (std::abs(row.dot(w)) >= kFacingSensitivity)
      {
        facing++;
        break;
      }
    }
  }
  return facing;
}

Ambiguity unobservableDirections(const Ambiguity& a, const FacingView& reference, const FacingView& current,
                                 double length, int min_rays)
{
  Ambiguity u = a;
  u.weak = 0;
  u.directions.setZero();
  if (min_rays <= 0) return u;
  const auto few = static_cast<size_t>(min_rays);
  for (int k = 0; k < a.weak; k++)
  {
    const Eigen::Vector3d v = a.directions.col(k);
    if (raysFacing(reference, v, length, few) < few || raysFacing(current, v, length, few) < few)
      u.directions.col(u.weak++) = v;
  }
  return u;
}

void takePriorAlongWeak(Eigen::Vector3d& pose, Eigen::Matrix3d& cov, const Eigen::Vector3d& prior,
                        const Eigen::Matrix3d& prior_cov, const Ambiguity& a, double length)
{
  if (a.weak == 0) return;
  const Eigen::DiagonalMatrix<double, 3> S(1, 1, length);
  const Eigen::DiagonalMatrix<double, 3> Sinv(1, 1, 1 / length);
  const Eigen::Matrix3d cov_u = S * cov * S, prior_u = S * prior_cov * S;
  if (!cov_u.allFinite() || !(length > 0))
  {
    // A covariance findWeakDirections calls bad: the prior alone decides.
    pose = prior;
    cov = prior_cov;
    return;
  }
  Eigen::Vector3d d = prior - pose;
  d.z() = std::remainder(d.z(), 2 * M_PI);
  const Eigen::Vector3d du = S * d;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  Eigen::Matrix3d change = Eigen::Matrix3d::Zero();
  for (int k = 0; k < a.weak; k++)
  {
    const Eigen::Vector3d v = a.directions.col(k);
    // v is an eigenvector of cov_u: its variance mu along v is replaced by the prior's pi.
    const double mu = v.dot(cov_u * v), pi = std::max(0.0, v.dot(prior_u * v));
    shift += v.dot(du) * v;
    change += (pi - mu) * v * v.transpose();
  }
  pose += Sinv * shift;
  pose.z() = std::remainder(pose.z(), 2 * M_PI);
  cov += Sinv * change * Sinv;
}

}  // namespace swslam::tracking
