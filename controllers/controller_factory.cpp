#include "control_interface/wall_contacts.hpp"
#include "controllers/controller.hpp"

namespace swarmagg {

void turn_at_walls(std::span<const std::uint8_t> reflections, SwarmState& swarm) {
  for (std::size_t i = 0; i < reflections.size(); ++i) {
    if (reflections[i] & ReflectedX) swarm.heading[i].x = -swarm.heading[i].x;
    if (reflections[i] & ReflectedY) swarm.heading[i].y = -swarm.heading[i].y;
  }
}

Vec2 heading_away(std::span<const Neighbour> neighbours, double radius, Vec2 fallback) {
  Vec2 towards;
  for (const Neighbour& nb : neighbours) {
    if (nb.distance > radius) break;
    towards += nb.offset;
  }
  const double length = norm(towards);
  return length > 1e-12 ? towards * (-1.0 / length) : fallback;
}

}  // namespace swarmagg
