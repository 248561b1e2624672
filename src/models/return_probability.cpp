#include "models/return_probability.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "controllers/controller_registry.hpp"
#include "models/aggregate_shape.hpp"

namespace swarmagg {

double heading_capture_probability(double distance, double capture_radius, double reach) {
  if (distance <= capture_radius) return 1.0;
  if (reach <= distance - capture_radius) return 0.0;
  const double tangent = std::sqrt(distance * distance - capture_radius * capture_radius);
  double half_angle = std::asin(capture_radius / distance);
  if (reach < tangent) {
    // The heading whose path of length `reach` ends on the disc's edge (the near side:
    // paths of smaller angle enter the disc sooner).
    const double cosine = (distance * distance + reach * reach - capture_radius * capture_radius) /
                          (2.0 * distance * reach);
    half_angle = std::acos(std::clamp(cosine, -1.0, 1.0));
  }
  return half_angle / std::numbers::pi;
}

double return_probability(const WorldSpec& world, int size) {
  const ControllerSpec& controller = world.controller;
  if (size < 2 || !controller.leave) return 0.0;
  if (size == 2 && controller.isolated_wait == IsolatedWait::Resume) return 0.0;
  const double r = world.robots.radius;
  const double v = world.robots.speed;
  const double perception = controller_rules(world).allows(AgentState::Approach)
                                ? controller.approach_radius
                                : world.robots.detection_radius;
  const double start = aggregate_radius(r, size) - r;
  const double distance = start + controller.leave_timeout * v;
  const double capture = aggregate_radius(r, size - 1) - r + perception;
  const double reach = std::max(0.0, world.return_window() - controller.leave_timeout) * v;
  return heading_capture_probability(distance, capture, reach);
}

double attempt_return_probability(const WorldSpec& world, int size) {
  if (size < 2 || !world.controller.leave) return 0.0;
  const double rim_share = capped_periphery_agents(size) / size;
  return rim_share * return_probability(world, size) + (1.0 - rim_share);
}

}  // namespace swarmagg
