#include "rates/rate_tally.hpp"

#include <stdexcept>

namespace swarmagg {

RateTally::RateTally(int agent_count)
    : agents(agent_count),
      growths(static_cast<std::size_t>(agent_count) + 1, 0),
      searcher_aggregate_steps(static_cast<std::size_t>(agent_count) + 1, 0),
      aggregate_steps(static_cast<std::size_t>(agent_count) + 1, 0),
      initial_aggregates(static_cast<std::size_t>(agent_count) + 1, 0),
      attempts(static_cast<std::size_t>(agent_count) + 1, 0),
      escapes(static_cast<std::size_t>(agent_count) + 1, 0),
      leave_aggregate_steps(static_cast<std::size_t>(agent_count) + 1, 0),
      return_attempts(static_cast<std::size_t>(agent_count) + 1, 0),
      returns(static_cast<std::size_t>(agent_count) + 1, 0),
      return_steps(static_cast<std::size_t>(agent_count) + 1, 0),
      return_square_steps(static_cast<std::size_t>(agent_count) + 1, 0),
      returns_into(static_cast<std::size_t>(agent_count) + 1, 0),
      returning_searcher_steps(static_cast<std::size_t>(agent_count) + 1, 0),
      outer_radius(static_cast<std::size_t>(agent_count) + 1),
      rim(static_cast<std::size_t>(agent_count) + 1) {}

void RateTally::merge(const RateTally& other) {
  if (other.agents != agents) throw std::invalid_argument("RateTally::merge: agent counts differ");
  replicates += other.replicates;
  steps += other.steps;
  creations += other.creations;
  pair_steps += other.pair_steps;
  for (std::size_t m = 0; m < growths.size(); ++m) {
    growths[m] += other.growths[m];
    searcher_aggregate_steps[m] += other.searcher_aggregate_steps[m];
    aggregate_steps[m] += other.aggregate_steps[m];
    initial_aggregates[m] += other.initial_aggregates[m];
    attempts[m] += other.attempts[m];
    escapes[m] += other.escapes[m];
    leave_aggregate_steps[m] += other.leave_aggregate_steps[m];
    return_attempts[m] += other.return_attempts[m];
    returns[m] += other.returns[m];
    return_steps[m] += other.return_steps[m];
    return_square_steps[m] += other.return_square_steps[m];
    returns_into[m] += other.returns_into[m];
    returning_searcher_steps[m] += other.returning_searcher_steps[m];
    outer_radius[m].merge(other.outer_radius[m]);
    rim[m].merge(other.rim[m]);
  }
}

}  // namespace swarmagg
