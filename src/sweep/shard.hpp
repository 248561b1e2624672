#pragma once
// `--shard i/n`: shard i of n takes the runs whose index mod n is i - 1. Interleaving (not
// blocks) spreads every parameter point over the shards, so shards take similar time.
#include <string>

namespace swarmagg {

struct Shard {
  int index = 1;  // 1-based, as SLURM_ARRAY_TASK_ID usually is
  int count = 1;

  bool whole() const { return count == 1; }
  bool contains(int run_index) const { return run_index % count == index - 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// Reads "i/n" with 1 <= i <= n; anything else is an InputError.
Shard parse_shard(const std::string& text);

}  // namespace swarmagg
