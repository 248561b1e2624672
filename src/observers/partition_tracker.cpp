#include "observers/partition_tracker.hpp"

#include <algorithm>
#include <functional>
#include <numeric>

namespace swarmagg {

std::string partition_key(std::span<const std::int32_t> aggregate_sizes, int agent_count) {
  std::vector<std::int32_t> parts(aggregate_sizes.begin(), aggregate_sizes.end());
  std::sort(parts.begin(), parts.end(), std::greater<>());
  const int in_aggregates = std::accumulate(parts.begin(), parts.end(), 0);
  parts.insert(parts.end(), static_cast<std::size_t>(agent_count - in_aggregates), 1);
  std::string key;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (k > 0) key += '+';
    key += std::to_string(parts[k]);
  }
  return key;
}

void PartitionTracker::observe(const AggregateTracker& aggregates, int agent_count) {
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
  closed_[partition_key(current_, agent_count_)] += run_length_;
  run_length_ = 0;
}

std::map<std::string, std::int64_t> PartitionTracker::steps_by_partition() const {
  auto all = closed_;
  if (run_length_ > 0) all[partition_key(current_, agent_count_)] += run_length_;
  return all;
}

}  // namespace swarmagg
