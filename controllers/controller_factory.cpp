#include "control_interface/wall_contacts.hpp"
#include "controllers/controller.hpp"

namespace swarmagg {

void turn_at_walls(std::span<const std::uint8_t> reflections, SwarmState& swarm) {
  for (std::size_t i = 0; i < reflections.size(); ++i) {
    if (reflections[i] & ReflectedX) swarm.heading[i].x = -swarm.heading[i].x;
    if (reflections[i] & ReflectedY) swarm.heading[i].y = -swarm.heading[i].y;
  }
}

std::optional<Vec2> heading_away(std::span<const Neighbour> neighbours, double radius,
                                 double enclosed_fraction) {
  Vec2 towards;
  double lengths = 0.0;
  for (const Neighbour& nb : neighbours) {
    if (nb.distance > radius) break;
    towards += nb.offset;
    lengths += nb.distance;
  }
  const double length = norm(towards);
  if (length > 1e-12 * lengths && length > enclosed_fraction * lengths)
    return towards * (-1.0 / length);
  return std::nullopt;
}

}  // namespace swarmagg
