#include "observers/aggregate_lineage.hpp"

#include <algorithm>

namespace swarmagg {
namespace {

// How many distinct values `key` takes over sorted `links` (equal keys are adjacent when the
// key is the high half; for the low half the caller sorts by it first).
template <typename Key>
std::size_t distinct(std::span<const std::uint64_t> links, Key key) {
  std::size_t count = 0;
  for (std::size_t k = 0; k < links.size(); ++k) {
    count += static_cast<std::size_t>(k == 0 || key(links[k]) != key(links[k - 1]));
  }
  return count;
}

}  // namespace

void AggregateLineage::observe(std::span<const std::int32_t> aggregate_of, int count) {
  // The same labels are the same aggregates: nothing was born, died, merged or split.
  if (std::ranges::equal(aggregate_of, before_) && count == count_before_) return;
  links_.clear();
  if (before_.size() == aggregate_of.size()) {
    for (std::size_t agent = 0; agent < aggregate_of.size(); ++agent) {
      const std::int32_t now = aggregate_of[agent];
      const std::int32_t then = before_[agent];
      if (now >= 0 && then >= 0)
        links_.push_back(std::uint64_t{static_cast<std::uint32_t>(now)} << 32 |
                         static_cast<std::uint32_t>(then));
    }
  }
  std::ranges::sort(links_);
  links_.erase(std::unique(links_.begin(), links_.end()), links_.end());
  const std::span<const std::uint64_t> links(links_);
  const std::size_t now_linked = distinct(links, [](std::uint64_t l) { return l >> 32; });
  std::ranges::sort(links_, {}, [](std::uint64_t l) { return static_cast<std::uint32_t>(l); });
  const std::size_t before_linked =
      distinct(links, [](std::uint64_t l) { return static_cast<std::uint32_t>(l); });
  counts_.births += static_cast<std::uint64_t>(count) - now_linked;
  counts_.deaths += static_cast<std::uint64_t>(count_before_) - before_linked;
  counts_.merges += links.size() - now_linked;
  counts_.splits += links.size() - before_linked;
  before_.assign(aggregate_of.begin(), aggregate_of.end());
  count_before_ = count;
}

}  // namespace swarmagg
