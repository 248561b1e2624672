#include "run/measured_run.hpp"

#include "run/rate_collector.hpp"

namespace swarmagg {

MeasuredRun run_world_measuring(const WorldSpec& spec, const RunOptions& options,
                                bool rates_asked) {
  if (!rates_asked && spec.model.initial_state != InitialState::Measured)
    return {run_world(spec, options), std::nullopt};
  RateCollector collector(spec);
  RunOptions measuring = options;
  measuring.observers = both_observers(
      options.observers, [&collector](int index) { return collector.observer(index); });
  MeasuredRun run{run_world(spec, measuring), std::nullopt};
  run.rates = collector.total();
  return run;
}

}  // namespace swarmagg
