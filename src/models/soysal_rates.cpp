#include "models/soysal_rates.hpp"

#include <algorithm>
#include <numbers>

#include "config/leave_law.hpp"
#include "models/aggregate_shape.hpp"

namespace swarmagg {

double soysal_leavers(const WorldSpec& world, LeavingVariant variant, int size) {
  if (variant == LeavingVariant::Original) return size;
  return world.model.periphery_cap ? capped_periphery_agents(size) : periphery_agents(size);
}

SoysalRates soysal_rates(const WorldSpec& world, LeavingVariant variant) {
  const int n = world.robots.count;
  const double r = world.robots.radius;
  const double approach = world.controller.approach_radius;
  const double v = world.robots.speed;
  const double sweep_per_length = 2.0 * world.engine.dt / world.arena.area();
  SoysalRates rates;
  rates.agents = n;
  rates.pair_up = sweep_per_length * approach * (4.0 / std::numbers::pi) * v;
  rates.join.assign(n + 1, 0.0);
  rates.leave.assign(n + 1, 0.0);
  for (int i = 2; i <= n; ++i) {
    if (world.controller.join) {
      rates.join[i] = sweep_per_length * (aggregate_radius(r, i) + approach - r) * v;
    }
    if (world.controller.leave) {
      rates.leave[i] = soysal_leavers(world, variant, i) *
                       leave_probability(world.controller.leave_law, world.controller.p0, i);
    }
  }
  return rates;
}

}  // namespace swarmagg
