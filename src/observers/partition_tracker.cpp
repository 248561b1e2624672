#include "observers/partition_tracker.hpp"

#include <algorithm>
#include <charconv>
#include <functional>
#include <numeric>

namespace swarmagg {
namespace {

// Writes the key of a partition whose aggregate sizes are already in decreasing order into
// `key`, reusing its storage.
void write_key(std::span<const std::int32_t> sorted_sizes, int agent_count, std::string& key) {
  key.clear();
  auto append = [&key](std::int32_t part) {
    if (!key.empty()) key += '+';
    char digits[16];
    const auto end = std::to_chars(digits, digits + sizeof digits, part).ptr;
    key.append(digits, end);
  };
  for (const std::int32_t part : sorted_sizes) append(part);
  const int in_aggregates = std::accumulate(sorted_sizes.begin(), sorted_sizes.end(), 0);
  for (int k = in_aggregates; k < agent_count; ++k) append(1);
}

}  // namespace

std::string partition_key(std::span<const std::int32_t> aggregate_sizes, int agent_count) {
  std::vector<std::int32_t> parts(aggregate_sizes.begin(), aggregate_sizes.end());
  std::sort(parts.begin(), parts.end(), std::greater<>());
  std::string key;
  write_key(parts, agent_count, key);
  return key;
}

void PartitionTracker::observe(const AggregateTracker& aggregates, int agent_count) {
  // At most agent_count / 2 aggregates: reserving that once keeps assign() from
  // reallocating as their number grows.
  const auto most = static_cast<std::size_t>(agent_count / 2);
  if (scratch_.capacity() < most) scratch_.reserve(most);
  if (current_.capacity() < most) current_.reserve(most);
  // Partitions change rarely, so only a change of the sorted sizes costs a map update.
  scratch_.assign(aggregates.sizes().begin(), aggregates.sizes().end());
  std::sort(scratch_.begin(), scratch_.end(), std::greater<>());
  if (run_length_ > 0 && (scratch_ != current_ || agent_count != agent_count_)) close_run();
  if (run_length_ == 0) {
    current_.swap(scratch_);
    agent_count_ = agent_count;
  }
  ++run_length_;
}

void PartitionTracker::close_run() {
  write_key(current_, agent_count_, key_);
  if (const auto it = closed_.find(key_); it != closed_.end()) {
    it->second += run_length_;
  } else {
    closed_.emplace(key_, run_length_);
  }
  run_length_ = 0;
}

std::map<std::string, std::int64_t> PartitionTracker::steps_by_partition() const {
  std::map<std::string, std::int64_t> all(closed_.begin(), closed_.end());
  if (run_length_ > 0) {
    std::string key;
    write_key(current_, agent_count_, key);
    all[key] += run_length_;
  }
  return all;
}

}  // namespace swarmagg
