#pragma once
// A run that measures the model terms (events over exposure) as it goes, through a
// RateCollector on every replicate: what `swarmagg run --rates`, `swarmagg rates`,
// `reproduce` and the Python module's run() and rates() share.
#include <optional>

#include "config/world_spec.hpp"
#include "rates/rate_tally.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {

struct MeasuredRun {
  RunResult result;
  std::optional<RateTally> rates;  // every replicate's tally, merged, when measured
};

// Runs the world as run_world does (options.observers still watch every replicate). It
// measures when `rates_asked`, and always for a world whose model starts from the measured
// initial state (model.initial_state: measured), since its predictions need the rates.
MeasuredRun run_world_measuring(const WorldSpec& spec, const RunOptions& options, bool rates_asked);

}  // namespace swarmagg
