#include <swslam/graph/coupling_policy.h>

#include <swslam/graph/normal_equations.h>

#include <algorithm>

namespace swslam::graph
{
size_t minDecoupled(size_t edges)
{
  return std::max<size_t>(1, static_cast<size_t>(kMinDecoupledShare * static_cast<double>(edges)));
}

namespace
{
bool decouples(Coupling coupling)
{
  return coupling == Coupling::DecoupleWeak || coupling == Coupling::DecoupleWeakAfresh;
}
}  // namespace

void prepareCoupling(CoupledSystem& sys, Coupling coupling, int free_blocks,
                     const std::vector<std::pair<int, int>>& pairs, const WeakEdges& weak)
{
  const size_t min_decoupled = minDecoupled(pairs.size());
  if (coupling == Coupling::Exact && NormalEquations::fillPerColumnOf(free_blocks, pairs) > kDenseFillPerColumn)
    sys.prepareDecoupled(free_blocks, pairs, weak(kPreconditionerWeight), min_decoupled);
  else if (coupling == Coupling::DecoupleWeakAfresh)
    sys.prepareDecoupled(free_blocks, pairs, weak(kDecoupledWeight), min_decoupled);
  else
  {
    sys.prepare(free_blocks, pairs, decouples(coupling));
    if (decouples(coupling)) sys.decouple(weak(kDecoupledWeight), min_decoupled);
  }
}

void decoupleAfterStep(CoupledSystem& sys, Coupling coupling, size_t edges, const WeakEdges& weak)
{
  if (decouples(coupling)) sys.decouple(weak(kDecoupledWeight), minDecoupled(edges));
}

}  // namespace swslam::graph
