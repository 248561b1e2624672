#pragma once
// One recorded row of a replicate's time series (docs/reference/outputs.md, timeseries.csv).
#include <cstdint>

#include "control_interface/event_counts.hpp"
#include "observers/aggregate_tracker.hpp"
#include "observers/swarm_snapshot.hpp"

namespace swarmagg {

struct StateCounts {
  int searching = 0;  // GO
  int waiting = 0;
  int leaving = 0;
  int approaching = 0;
};

struct TimeseriesRow {
  int replicate = 0;
  std::int64_t step = 0;
  double time = 0.0;
  int noa = 0;
  StateCounts states;
  int largest = 0;
  EventCounts events;
};

StateCounts count_states(std::span<const AgentState> states);
TimeseriesRow observe_row(int replicate, const SwarmSnapshot& snapshot,
                          const AggregateTracker& aggregates, const EventCounts& events);

}  // namespace swarmagg
