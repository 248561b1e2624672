#pragma once
// Which states a run records (a timeseries row; the rate collector's geometry): the state
// after every run.record_every-th step, and after the last.
#include <cstdint>

#include "config/world_spec.hpp"

namespace swarmagg {

inline bool is_recorded_step(const WorldSpec& spec, std::int64_t step) {
  return step % spec.run.record_every == 0 || step == spec.steps();
}

// How many states each replicate records: steps 0, K, 2K, ... and the last.
inline std::int64_t recorded_rows(const WorldSpec& spec) {
  const std::int64_t steps = spec.steps();
  return steps / spec.run.record_every + 1 + (steps % spec.run.record_every != 0);
}

}  // namespace swarmagg
