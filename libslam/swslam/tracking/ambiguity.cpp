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

double rotationLength(const std::vector<Eigen::Vector2d>& points)
{
  double sum = 0;
  for (const auto& p : points) sum += p.squaredNorm();
  if (points.empty() || !(sum > 0) || !std::isfinite(sum)) return 1.0;
  return std::sqrt(sum / static_cast<double>(points.size()));
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
