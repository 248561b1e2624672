#pragma once
// Soysal's observable: the partition of the swarm (every aggregate's size, plus a part of
// size 1 per agent in no aggregate) and how many steps the swarm spends in each.
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "observers/aggregate_tracker.hpp"

namespace swarmagg {

// "3+1+1": parts in decreasing order joined by '+'.
std::string partition_key(std::span<const std::int32_t> aggregate_sizes, int agent_count);

class PartitionTracker {
 public:
  // Counts one step spent in the partition the tracker describes. Allocates only when the
  // swarm enters a partition it has never been in (runs every step of a Soysal run).
  void observe(const AggregateTracker& aggregates, int agent_count);
  // Steps spent in each partition so far.
  std::map<std::string, std::int64_t> steps_by_partition() const;

 private:
  void close_run();

  std::vector<std::int32_t> current_;  // sorted aggregate sizes of the current run
  std::vector<std::int32_t> scratch_;
  std::int64_t run_length_ = 0;
  int agent_count_ = 0;
  std::string key_;  // the current run's key, rebuilt in place when the run closes
  // Transparent comparison: a key already present is found without a string copy.
  std::map<std::string, std::int64_t, std::less<>> closed_;
};

}  // namespace swarmagg
