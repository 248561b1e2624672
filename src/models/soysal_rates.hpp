#pragma once
// Per-step transition probabilities of the Soysal partition model (docs/models.md) for one world
// and leaving variant, with the experiment rules applied (join: false -> no joining,
// leave: false -> no leaving). Encounter probabilities are swept areas per step:
//   P_e(1) = 2 s_a (4v/pi) dt / A (two moving agents, mean relative speed 4v/pi);
//   P_e(i) = 2 rho_i v dt / A, rho_i = R_agg(i) + s_a - r, R_agg(i) = r 1.20 i^0.48.
// An aggregate of size i loses an agent with L(i) = i P_l(i) (original) or periph(i) P_l(i)
// (peripheral; periph capped at i when model.periphery_cap), P_l(i) = p0, p0/i or p0/i^2.
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

struct SoysalRates {
  int agents = 0;
  double pair_up = 0.0;       // P_e(1), per pair of free agents
  std::vector<double> join;   // [i] P_e(i), per (free agent, aggregate of size i) pair
  std::vector<double> leave;  // [i] L(i), per aggregate of size i >= 2
};

// The agents of a size-i aggregate able to leave: i (original) or its periphery (peripheral).
double soysal_leavers(const WorldSpec& world, LeavingVariant variant, int size);

SoysalRates soysal_rates(const WorldSpec& world, LeavingVariant variant);

}  // namespace swarmagg
