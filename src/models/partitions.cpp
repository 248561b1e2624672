#include "models/partitions.hpp"

#include <algorithm>
#include <limits>

namespace swarmagg {

namespace {

// Appends to `out` every partition of `remaining` into parts <= `largest_part`, each
// prefixed by `prefix`.
void extend_partitions(int remaining, int largest_part, Partition& prefix,
                       std::vector<Partition>& out) {
  if (remaining == 0) {
    out.push_back(prefix);
    return;
  }
  for (int part = std::min(remaining, largest_part); part >= 1; --part) {
    prefix.push_back(part);
    extend_partitions(remaining - part, part, prefix, out);
    prefix.pop_back();
  }
}

}  // namespace

long long partition_count(int n) {
  constexpr long long kMost = std::numeric_limits<long long>::max();
  constexpr int kLargestCounted = 405;  // p(406) > kMost; p grows with n
  if (n > kLargestCounted) return kMost;
  // ways[k]: partitions of k into parts no larger than the part sizes added so far.
  std::vector<long long> ways(std::max(n, 0) + 1, 0);
  ways[0] = 1;
  for (int part = 1; part <= n; ++part) {
    for (int k = part; k <= n; ++k) ways[k] += ways[k - part];
  }
  return ways[std::max(n, 0)];
}

std::vector<Partition> integer_partitions(int n) {
  std::vector<Partition> out;
  Partition prefix;
  extend_partitions(n, n, prefix, out);
  return out;
}

std::string partition_label(const Partition& partition) {
  std::string label;
  for (const int part : partition) {
    if (!label.empty()) label += '+';
    label += std::to_string(part);
  }
  return label;
}

int free_agents(const Partition& partition) {
  return static_cast<int>(std::count(partition.begin(), partition.end(), 1));
}

int aggregate_count(const Partition& partition) {
  return static_cast<int>(partition.size()) - free_agents(partition);
}

int largest_aggregate(const Partition& partition) {
  return !partition.empty() && partition.front() >= 2 ? partition.front() : 0;
}

}  // namespace swarmagg
