#include "observers/leave_tally.hpp"

#include <algorithm>

namespace swarmagg {
namespace {

void add_by_size(std::vector<std::int64_t>& into, const std::vector<std::int64_t>& from) {
  if (into.size() < from.size()) into.resize(from.size(), 0);
  std::transform(from.begin(), from.end(), into.begin(), into.begin(), std::plus<>());
}

}  // namespace

void LeaveTally::resize(int agent_count) {
  const auto sizes = static_cast<std::size_t>(agent_count) + 1;
  attempts_by_size.resize(sizes, 0);
  escapes_by_size.resize(sizes, 0);
  aggregate_steps_by_size.resize(sizes, 0);
  return_attempts_by_size.resize(sizes, 0);
  returns_by_size.resize(sizes, 0);
  return_steps_by_size.resize(sizes, 0);
  return_square_steps_by_size.resize(sizes, 0);
  returns_into_size.resize(sizes, 0);
  returning_aggregate_steps_by_size.resize(sizes, 0);
}

// Divided by the steps per tu rather than multiplied by dt: 119754 steps of 0.1 tu give
// 11975.4, not 11975.400000000001.
double LeaveTally::aggregate_time(int size, double dt) const {
  const auto k = static_cast<std::size_t>(size);
  if (k >= aggregate_steps_by_size.size()) return 0.0;
  return static_cast<double>(aggregate_steps_by_size[k]) / (1.0 / dt);
}

LeaveTally& LeaveTally::operator+=(const LeaveTally& other) {
  attempts += other.attempts;
  escapes += other.escapes;
  add_by_size(attempts_by_size, other.attempts_by_size);
  add_by_size(escapes_by_size, other.escapes_by_size);
  add_by_size(aggregate_steps_by_size, other.aggregate_steps_by_size);
  add_by_size(return_attempts_by_size, other.return_attempts_by_size);
  add_by_size(returns_by_size, other.returns_by_size);
  add_by_size(return_steps_by_size, other.return_steps_by_size);
  add_by_size(return_square_steps_by_size, other.return_square_steps_by_size);
  add_by_size(returns_into_size, other.returns_into_size);
  add_by_size(returning_aggregate_steps_by_size, other.returning_aggregate_steps_by_size);
  return *this;
}

}  // namespace swarmagg
