#pragma once
// Soysal's leave probability P_l(i) per step for an agent whose aggregate has `size`
// agents (docs/controllers.md): p0, p0 / i or p0 / i^2. Shared by the controller and the partition
// model so the simulation and the prediction can never disagree on it.
#include "config/world_spec.hpp"

namespace swarmagg {

double leave_probability(LeaveLaw law, double p0, int size);

}  // namespace swarmagg
