#pragma once
// The per-step event probabilities of the Bayindir model (docs/models.md) for one world and
// creation variant, with the experiment rules applied: join: false switches growth off,
// leave: false switches dissipation and shrinking off, p is controller.p_leave. Sizes are
// truncated at N (an aggregate of all N agents cannot grow). A collision-controller world
// forms no aggregates: its encounters are only counted.
#include <vector>

#include "config/world_spec.hpp"
#include "models/kinetic_rate.hpp"

namespace swarmagg {

struct BayindirRates {
  int agents = 0;
  bool forms_aggregates = true;
  PairRate creation;  // expected creations (or encounters) per step among y searchers
  // [m]: probability per step that one given searcher joins one given aggregate of size m,
  // 2 rho_m v dt / A with capture radius rho_m = s + R1(m) - s/4.
  std::vector<double> growth;
  // [m]: probability per step that an aggregate of size m loses an agent: 2p for m = 2
  // (dissipation), p * min(m, periph(m)) for m >= 3 (shrinking).
  std::vector<double> loss;
};

// The agent radius the model's aggregate radius R1(m) is built on: r_eff = s/4 (docs/models.md
// [choice]), not robots.radius.
double bayindir_agent_radius(const WorldSpec& world);

// Throws InputError when a per-step probability exceeds 1 (dt too coarse for the model).
BayindirRates bayindir_rates(const WorldSpec& world, CreationVariant variant);

}  // namespace swarmagg
