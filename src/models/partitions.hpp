#pragma once
// Integer partitions of N, the states of the Soysal model: the multiset of aggregate sizes
// with every free agent a part of size 1, parts in decreasing order, written "3+1+1".
#include <string>
#include <vector>

namespace swarmagg {

using Partition = std::vector<int>;  // parts, decreasing

// How many partitions n has, p(n), without listing them (Euler's recurrence by parts); the
// largest long long when p(n) exceeds it (from n = 406 on), never a wrapped count.
long long partition_count(int n);

// All partitions of n in reverse lexicographic order: (n), (n-1, 1), ..., (1, ..., 1).
std::vector<Partition> integer_partitions(int n);

std::string partition_label(const Partition& partition);

int free_agents(const Partition& partition);        // parts of size 1
int aggregate_count(const Partition& partition);    // parts of size >= 2
int largest_aggregate(const Partition& partition);  // largest part >= 2, 0 without one

}  // namespace swarmagg
