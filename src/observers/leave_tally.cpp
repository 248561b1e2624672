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
}

LeaveTally& LeaveTally::operator+=(const LeaveTally& other) {
  attempts += other.attempts;
  escapes += other.escapes;
  add_by_size(attempts_by_size, other.attempts_by_size);
  add_by_size(escapes_by_size, other.escapes_by_size);
  add_by_size(aggregate_steps_by_size, other.aggregate_steps_by_size);
  return *this;
}

}  // namespace swarmagg
