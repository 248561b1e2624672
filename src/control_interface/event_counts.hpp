#pragma once
// Cumulative aggregation events of one replicate (docs/models.md).
#include <algorithm>
#include <cstdint>
#include <span>

namespace swarmagg {

struct EventCounts {
  std::uint64_t creations = 0;     // two searching agents met and formed an aggregate
  std::uint64_t growths = 0;       // a searching agent joined an aggregate
  std::uint64_t dissipations = 0;  // an aggregate of two lost an agent
  std::uint64_t shrinks = 0;       // an aggregate of three or more lost an agent
  std::uint64_t encounters = 0;    // first contacts within s of any pair
};

// Counts the leave of an agent of aggregate `aggregate` (-1: none). Members of one aggregate
// leaving in the same decision are counted one after another (docs/models.md): an aggregate of two
// that both leave dissipates once; of five losing two, shrinks twice. `members_left` starts
// the decision as the aggregates' sizes.
inline void count_leave(std::int32_t aggregate, std::span<std::int32_t> members_left,
                        EventCounts& events) {
  if (aggregate < 0) return;
  std::int32_t& left = members_left[static_cast<std::size_t>(aggregate)];
  if (left >= 3) ++events.shrinks;
  if (left == 2) ++events.dissipations;
  --left;
}

// Counts one growth of an aggregate of `joined_size` agents in `growths_by_size` ([m], the
// last entry for larger m); nothing when it is empty (nobody reads them).
inline void count_growth_by_size(std::span<std::uint64_t> growths_by_size, int joined_size) {
  if (growths_by_size.empty()) return;
  const auto last = static_cast<int>(growths_by_size.size()) - 1;
  ++growths_by_size[static_cast<std::size_t>(std::clamp(joined_size, 0, last))];
}

}  // namespace swarmagg
