#include "observers/timeseries_row.hpp"

namespace swarmagg {

StateCounts count_states(std::span<const AgentState> states) {
  StateCounts counts;
  for (const AgentState s : states) {
    switch (s) {
      case AgentState::Go:
        ++counts.searching;
        break;
      case AgentState::Wait:
        ++counts.waiting;
        break;
      case AgentState::Leave:
        ++counts.leaving;
        break;
      case AgentState::Approach:
        ++counts.approaching;
        break;
    }
  }
  return counts;
}

TimeseriesRow observe_row(int replicate, const SwarmSnapshot& snapshot,
                          const AggregateTracker& aggregates, const EventCounts& events) {
  TimeseriesRow row;
  row.replicate = replicate;
  row.step = snapshot.step;
  row.time = snapshot.time;
  row.noa = aggregates.count();
  row.states = count_states(snapshot.states);
  row.largest = aggregates.largest();
  row.events = events;
  return row;
}

}  // namespace swarmagg
