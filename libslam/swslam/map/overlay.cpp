#include <swslam/map/overlay.h>

#include <stdexcept>
#include <string>

namespace swslam::map
{
void checkOverlay(const Overlay& overlay)
{
  for (const OverlayEdge& e : overlay.edges)
    if (e.from >= overlay.nodes.size() || e.to >= overlay.nodes.size())
      throw std::invalid_argument("map picture: edge (" + std::to_string(e.from) + ", " + std::to_string(e.to) +
                                  ") refers to a node beyond the " + std::to_string(overlay.nodes.size()) +
                                  " given");
}

}  // namespace swslam::map
