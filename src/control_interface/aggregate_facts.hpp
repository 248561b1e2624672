#pragma once
// The aggregate bookkeeping a controller may read (the model assumes agents know the size of
// the aggregate they belong to): plain views of the states the decision starts from, not the
// tracker that computes them.
#include <cstdint>
#include <span>

namespace swarmagg {

struct AggregateFacts {
  // Size of every aggregate, by aggregate index.
  std::span<const std::int32_t> sizes;
  // Aggregate index of each agent, or -1 when it belongs to no aggregate.
  std::span<const std::int32_t> aggregate_of;
  // Size of each agent's aggregate (0 when in none).
  std::span<const std::int32_t> size_of_agent;
};

}  // namespace swarmagg
