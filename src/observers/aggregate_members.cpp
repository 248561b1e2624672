#include "observers/aggregate_members.hpp"

namespace swarmagg {

void AggregateMembers::build(const AggregateTracker& aggregates) {
  const std::span<const std::int32_t> sizes = aggregates.sizes();
  const std::span<const std::uint32_t> aggregated = aggregates.aggregated_agents();
  const std::span<const std::int32_t> aggregate_of = aggregates.aggregate_of();
  if (members_.capacity() < aggregate_of.size()) {
    // The bounds: every agent in an aggregate, every aggregate of two.
    members_.reserve(aggregate_of.size());
    offsets_.reserve(aggregate_of.size() / 2 + 1);
    cursor_.reserve(aggregate_of.size() / 2);
  }
  offsets_.resize(sizes.size() + 1);
  cursor_.resize(sizes.size());
  offsets_[0] = 0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    cursor_[k] = offsets_[k];
    offsets_[k + 1] = offsets_[k] + static_cast<std::uint32_t>(sizes[k]);
  }
  members_.resize(aggregated.size());
  // The tracker lists aggregated agents in index order, so each aggregate's span is sorted.
  for (const std::uint32_t i : aggregated) members_[cursor_[aggregate_of[i]]++] = i;
}

}  // namespace swarmagg
