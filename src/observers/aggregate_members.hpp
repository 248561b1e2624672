#pragma once
// The members of every aggregate, grouped: the agents of aggregate k (the tracker's index)
// as one contiguous span, in agent index order. Rebuilt from the tracker in time
// proportional to the agents in aggregates; allocates only the first time (its buffers
// take their bounds, every agent in an aggregate, then), so it can run every step.
#include <cstdint>
#include <span>
#include <vector>

#include "control_interface/neighbour_lists.hpp"
#include "observers/aggregate_tracker.hpp"

namespace swarmagg {

class AggregateMembers {
 public:
  void build(const AggregateTracker& aggregates);

  int count() const { return static_cast<int>(offsets_.size()) - 1; }
  std::span<const AgentId> of(int aggregate) const {
    const auto k = static_cast<std::size_t>(aggregate);
    return {members_.data() + offsets_[k], members_.data() + offsets_[k + 1]};
  }

 private:
  std::vector<std::uint32_t> offsets_{0};  // aggregate k's members: [offsets_[k], offsets_[k+1])
  std::vector<std::uint32_t> cursor_;
  std::vector<AgentId> members_;
};

}  // namespace swarmagg
