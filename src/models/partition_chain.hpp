#pragma once
// The Soysal model as a continuous-time Markov chain over partitions of N, with rates per
// step. From f free agents and c_i aggregates of size i:
//   pair-up (1,1) -> (2):     f (f-1)/2 P_e(1)     join (1,i) -> (i+1): f c_i P_e(i)
//   leave (i) -> (i-1,1), i >= 3: c_i L(i)          dissolve (2) -> (1,1): c_2 L(2)
// The states are the partitions reachable from all agents free (every partition unless a
// rule switches events off), in integer_partitions order.
#include <Eigen/SparseCore>
#include <vector>

#include "models/partitions.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {

using Generator = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct PartitionChain {
  std::vector<Partition> states;
  Generator generator;     // Q: off-diagonal rates, rows summing to 0
  int all_free = 0;        // index of (1, ..., 1), the initial state
  bool recurrent = false;  // every state returns to all free: a unique stationary law exists
};

PartitionChain build_partition_chain(const SoysalRates& rates);

}  // namespace swarmagg
