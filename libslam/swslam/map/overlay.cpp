#include <swslam/map/overlay.h>

#include <stdexcept>
#include <string>

namespace swslam::map
{
size_t Overlay::countByPrediction() const
{
  size_t n = 0;
  for (const bool b : by_prediction) n += b ? 1 : 0;
  return n;
}

void checkOverlay(const Overlay& overlay)
{
  if (!overlay.by_prediction.empty() && overlay.by_prediction.size() != overlay.trajectory.size())
    throw std::invalid_argument("map picture: " + std::to_string(overlay.by_prediction.size()) +
                                " marks of the prediction for a trajectory of " +
                                std::to_string(overlay.trajectory.size()) + " poses");
  for (const OverlayEdge& e : overlay.edges)
    if (e.from >= overlay.nodes.size() || e.to >= overlay.nodes.size())
      throw std::invalid_argument("map picture: edge (" + std::to_string(e.from) + ", " + std::to_string(e.to) +
                                  ") refers to a node beyond the " + std::to_string(overlay.nodes.size()) +
                                  " given");
}

}  // namespace swslam::map
