#include <swslam/graph/truncated.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swslam::graph
{
double gncTlsWeight(double r2, double c2, double mu)
{
  if (r2 <= c2 * mu / (mu + 1)) return 1.0;
  if (r2 >= c2 * (mu + 1) / mu) return 0.0;
  return std::sqrt(c2 * mu * (mu + 1) / r2) - mu;
}

double truncatedCost(const GraphProblem& problem, const OutlierGates& gates)
{
  // The chi2 of every edge, less the part of each robustified edge beyond its gate.
  const std::vector<double> r = robustResiduals(problem);
  double cost = graphChi2(problem);
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    const double g = gates.of(problem.edges[k]);
    if (problem.edges[k].robust && r[k] > g) cost -= r[k] * r[k] - g * g;
  }
  return cost;
}

std::vector<double> graduatedTls(const std::vector<char>& robust, const std::vector<double>& c2, double mu0,
                                 const std::function<void(const std::vector<double>&)>& solve,
                                 const std::function<double(size_t)>& squared)
{
  const double inf = std::numeric_limits<double>::infinity();
  const size_t count = robust.size();
  std::vector<double> w(count, 1.0);
  for (size_t k = 0; k < count; ++k)
    if (robust[k] && squared(k) == inf) w[k] = 0;
  double mu = mu0;
  if (mu <= 0)
  {
    solve(w);
    double largest = 0;  // of r2 / c2
    for (size_t k = 0; k < count; ++k)
      if (robust[k] && w[k] > 0) largest = std::max(largest, squared(k) / c2[k]);
    if (largest <= 1) return w;  // every residual within its gate: nothing to decide
    mu = 1 / (2 * largest - 1);
  }
  for (size_t round = 0; round < kGncMaxRounds; ++round, mu *= kGncMuFactor)
  {
    bool binary = true;
    for (size_t k = 0; k < count; ++k)
    {
      if (!robust[k]) continue;
      const double r2 = squared(k);
      w[k] = r2 == inf ? 0.0 : gncTlsWeight(r2, c2[k], mu);
      binary = binary && (w[k] == 0.0 || w[k] == 1.0);
    }
    solve(w);
    if (binary) break;
  }
  return w;
}

}  // namespace swslam::graph
