#include "models/bayindir_rates.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "models/aggregate_shape.hpp"

namespace swarmagg {

double bayindir_agent_radius(const WorldSpec& world) {
  return world.robots.detection_radius / 4.0;
}

namespace {

std::vector<double> growth_probabilities(const WorldSpec& world) {
  const int n = world.robots.count;
  std::vector<double> growth(n + 1, 0.0);
  if (!world.controller.join) return growth;
  const double s = world.robots.detection_radius;
  const double effective_radius = bayindir_agent_radius(world);
  for (int m = 2; m < n; ++m) {
    const double capture_radius = s + aggregate_radius(effective_radius, m) - effective_radius;
    growth[m] = 2.0 * capture_radius * world.robots.speed * world.engine.dt / world.arena.area();
  }
  return growth;
}

std::vector<double> loss_probabilities(const WorldSpec& world) {
  const int n = world.robots.count;
  std::vector<double> loss(n + 1, 0.0);
  if (!world.controller.leave) return loss;
  const double p = world.controller.p_leave;
  if (n >= 2) loss[2] = 2.0 * p;
  for (int m = 3; m <= n; ++m) loss[m] = p * capped_periphery_agents(m);
  return loss;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// Sufficient conditions for the expected-value equations to keep every count >= 0 and for
// the stochastic draws to be probabilities: a searcher is consumed with total probability
// <= 1 per step, and an aggregate grows or loses an agent with total probability <= 1 (the
// chain has at most one event per searcher, and one per aggregate, in a step). Growth and
// creation scale with engine.dt; the leave probability is per step and the periphery grows
// with the aggregate, so the largest aggregates a world allows (N members) can exceed 1 at
// any dt.
void check_probabilities(const BayindirRates& rates) {
  const int n = rates.agents;
  const double per_searcher_creation = 2.0 * rates.creation.at(n) / std::max(1, n);
  double per_searcher_growth = 0.0;  // sum n_m g_m <= N max_m(g_m / m): g_m / m decreases
  for (int m = 2; m <= n; ++m) {
    per_searcher_growth = std::max(per_searcher_growth, rates.growth[m] / m * n);
  }
  if (per_searcher_creation + per_searcher_growth > 1.0) {
    throw InputError("model: a searcher's creation and growth probabilities per step sum to " +
                     number_text(per_searcher_creation + per_searcher_growth) +
                     " (above 1) in this world; reduce engine.dt");
  }
  for (int m = 2; m <= n; ++m) {
    if (rates.loss[m] <= 1.0) continue;
    throw InputError(
        "model: an aggregate of " + std::to_string(m) + " members (this world allows " +
        std::to_string(n) + ") loses a member with probability " + number_text(rates.loss[m]) +
        " per step (above 1): its rim leaves at controller.p_leave per member and step, which "
        "engine.dt does not change, so the model cannot describe aggregates that large at this "
        "p_leave (use fewer agents or a smaller p_leave)");
  }
  for (int m = 2; m <= n; ++m) {
    if (n * rates.growth[m] + rates.loss[m] <= 1.0) continue;
    throw InputError("model: an aggregate of " + std::to_string(m) +
                     " members gains or loses a member with probability " +
                     number_text(n * rates.growth[m] + rates.loss[m]) +
                     " per step (above 1; losses " + number_text(rates.loss[m]) +
                     "); reduce engine.dt");
  }
}

}  // namespace

BayindirRates bayindir_rates(const WorldSpec& world, CreationVariant variant) {
  BayindirRates rates;
  rates.agents = world.robots.count;
  // The collision check's worlds are modelled by their encounters only.
  rates.forms_aggregates = controller_rules(world).model != ModelFamily::Encounters;
  rates.creation = creation_per_step(world, variant);
  if (rates.forms_aggregates) {
    rates.growth = growth_probabilities(world);
    rates.loss = loss_probabilities(world);
  } else {
    rates.growth.assign(rates.agents + 1, 0.0);
    rates.loss.assign(rates.agents + 1, 0.0);
  }
  check_probabilities(rates);
  return rates;
}

}  // namespace swarmagg
