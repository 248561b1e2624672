#include "models/partition_chain.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <set>

namespace swarmagg {

namespace {

struct Move {
  Partition target;
  double rate = 0.0;
};

// Replaces one part `from` (0: none) by the parts `to` (0s ignored), keeping order.
Partition replace_part(const Partition& partition, int from, std::initializer_list<int> to) {
  Partition next = partition;
  if (from != 0) next.erase(std::find(next.begin(), next.end(), from));
  for (const int part : to) {
    if (part != 0) next.push_back(part);
  }
  std::sort(next.begin(), next.end(), std::greater<>());
  return next;
}

std::vector<Move> moves_from(const Partition& partition, const SoysalRates& rates) {
  std::vector<Move> moves;
  const int free = free_agents(partition);
  if (free >= 2 && rates.pair_up > 0.0) {
    const Partition paired = replace_part(replace_part(partition, 1, {}), 1, {2});
    moves.push_back({paired, 0.5 * free * (free - 1) * rates.pair_up});
  }
  std::map<int, int> aggregates_of_size;  // c_i
  for (const int part : partition) {
    if (part >= 2) ++aggregates_of_size[part];
  }
  for (const auto& [size, count] : aggregates_of_size) {
    if (free >= 1 && rates.join[size] > 0.0) {
      moves.push_back({replace_part(replace_part(partition, 1, {}), size, {size + 1}),
                       static_cast<double>(free) * count * rates.join[size]});
    }
    if (rates.leave[size] > 0.0) {
      moves.push_back({replace_part(partition, size, {size - 1, 1}), count * rates.leave[size]});
    }
  }
  return moves;
}

std::vector<Partition> reachable_states(const SoysalRates& rates, const Partition& start) {
  std::set<Partition> seen{start};
  std::deque<Partition> queue{start};
  while (!queue.empty()) {
    const Partition current = queue.front();
    queue.pop_front();
    for (const Move& move : moves_from(current, rates)) {
      if (seen.insert(move.target).second) queue.push_back(move.target);
    }
  }
  std::vector<Partition> states;
  for (Partition& partition : integer_partitions(rates.agents)) {
    if (seen.contains(partition)) states.push_back(std::move(partition));
  }
  return states;
}

}  // namespace

PartitionChain build_partition_chain(const SoysalRates& rates) {
  PartitionChain chain;
  const Partition all_free(rates.agents, 1);
  chain.states = reachable_states(rates, all_free);
  std::map<Partition, int> index;
  for (int i = 0; i < static_cast<int>(chain.states.size()); ++i) index[chain.states[i]] = i;
  chain.all_free = index.at(all_free);

  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < static_cast<int>(chain.states.size()); ++i) {
    double exit_rate = 0.0;
    for (const Move& move : moves_from(chain.states[i], rates)) {
      entries.emplace_back(i, index.at(move.target), move.rate);
      exit_rate += move.rate;
    }
    entries.emplace_back(i, i, -exit_rate);
  }
  const auto n = static_cast<Eigen::Index>(chain.states.size());
  chain.generator.resize(n, n);
  chain.generator.setFromTriplets(entries.begin(), entries.end());
  // Every state is reachable from all free by construction; all free is reachable back
  // (by agents leaving one at a time) when every aggregate size present can lose an agent.
  chain.recurrent = std::all_of(chain.states.begin(), chain.states.end(), [&](const Partition& p) {
    return std::all_of(p.begin(), p.end(),
                       [&](int part) { return part == 1 || rates.leave[part] > 0.0; });
  });
  return chain;
}

}  // namespace swarmagg
