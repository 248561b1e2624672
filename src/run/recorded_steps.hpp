#pragma once
// Which states a run records (a timeseries row; the rate collector's geometry): the state
// after every run.record_every-th step, and after the last.
#include <cstdint>

#include "config/world_spec.hpp"

namespace swarmagg {

inline bool is_recorded_step(const WorldSpec& spec, std::int64_t step) {
  return step % spec.run.record_every == 0 || step == spec.steps();
}

}  // namespace swarmagg
