#pragma once
// Standard normal draws for the synthetic-data tests of the rates module, from the counter
// generator (Box-Muller), so every trial is reproducible.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/rng.hpp"

namespace swarmagg::testing {

inline double standard_normal(const CounterRng& rng, std::uint64_t k, std::uint64_t slot) {
  const double u1 = 1.0 - rng.uniform(k, slot, Draw::Model, 0);
  const double u2 = rng.uniform(k, slot, Draw::Model, 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace swarmagg::testing
