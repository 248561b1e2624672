#pragma once
// Aggregates (docs/models.md): connected components of WAIT agents under "centre distance <= s",
// torus-aware, recomputed from scratch each time, so an aggregate split by a leaver counts
// as two. With partner links only (join: false), only the two agents of a pair are linked.
// Components of one agent are not aggregates. A step that changed no link (the same
// neighbour lists, states and partners) keeps the labels: it costs a comparison of the
// states, no labelling.
#include <cstdint>
#include <span>
#include <vector>

#include "control_interface/aggregate_facts.hpp"
#include "control_interface/neighbour_lists.hpp"
#include "core/agent_state.hpp"
#include "observers/union_find.hpp"

namespace swarmagg {

enum class AggregateLinks { Proximity, PartnersOnly };

class AggregateTracker {
 public:
  void update(const NeighbourLists& neighbours, const SwarmState& swarm, double detection_radius,
              AggregateLinks links);

  int count() const { return count_; }
  int largest() const { return largest_; }
  // Aggregate index of each agent (0 .. count-1, in order of each aggregate's lowest agent
  // index), or -1 when the agent belongs to no aggregate.
  std::span<const std::int32_t> aggregate_of() const { return aggregate_of_; }
  // Size of each agent's aggregate (0 when in none).
  std::span<const std::int32_t> size_of_agent() const { return size_of_agent_; }
  // Size of every aggregate, by aggregate index.
  std::span<const std::int32_t> sizes() const {
    return {sizes_.data(), static_cast<std::size_t>(count_)};
  }
  // What a controller may read of these (control_interface/aggregate_facts.hpp).
  AggregateFacts facts() const { return {sizes(), aggregate_of_, size_of_agent_}; }
  // The agents in an aggregate, in index order.
  std::span<const std::uint32_t> aggregated_agents() const {
    return {labelled_.data(), labelled_count_};
  }
  // The members of the aggregate `agent` is in (aggregate_of(agent) >= 0), in index order,
  // into `members` (replacing its contents). In time proportional to the aggregate's size,
  // so that looking at a few aggregates does not cost a pass over all of them.
  void members_of(std::uint32_t agent, std::vector<std::uint32_t>& members) const;

 private:
  void label_components(std::size_t n, std::span<const std::uint32_t> waiting);
  // Whether the links are those of the last update (and remembers these).
  bool same_links(const NeighbourLists& neighbours, const SwarmState& swarm, double radius,
                  AggregateLinks links);

  UnionFind sets_;
  AgentArray<std::int32_t> aggregate_of_;
  AgentArray<std::int32_t> size_of_agent_;
  // These two keep their bounds (n / 2 + 1 and n) so that labelling writes without branches;
  // only their first entries are valid.
  AgentArray<std::int32_t> sizes_;      // count_ valid
  AgentArray<std::uint32_t> labelled_;  // agents whose labels differ from -1 / 0
  std::size_t labelled_count_ = 0;
  AgentArray<std::uint32_t> waiting_;  // full length; the waiting agents come first
  int count_ = 0;
  int largest_ = 0;
  // What the last update linked from.
  const NeighbourLists* lists_ = nullptr;
  std::uint64_t generation_ = 0;
  AggregateLinks links_ = AggregateLinks::Proximity;
  double radius_ = 0.0;
  std::vector<AgentState> states_;
  std::vector<std::int32_t> partners_;
  const NeighbourLists* seen_lists_ = nullptr;  // the lists of the last update
  std::uint64_t seen_generation_ = 0;
};

}  // namespace swarmagg
