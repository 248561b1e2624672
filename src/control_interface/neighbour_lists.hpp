#pragma once
// Each agent's perceived agents after a step: every other agent whose centre lies within
// the world's sensing radius (torus-aware), nearest first. Stored as one flat array with
// per-agent offsets so refilling it every step allocates nothing after warm-up.
#include <cstdint>
#include <span>
#include <vector>

#include "core/agent_array.hpp"
#include "core/vec2.hpp"

namespace swarmagg {

using AgentId = std::uint32_t;

struct Neighbour {
  AgentId id = 0;
  Vec2 offset;  // from the perceiving agent to the neighbour (minimum image)
  double distance = 0.0;
};

// Two agents within sensing range of each other: i < j, offset from i to j.
struct ClosePair {
  AgentId i = 0;
  AgentId j = 0;
  Vec2 offset;
  double distance = 0.0;
};

class NeighbourLists {
 public:
  // Rebuilds every agent's list from the close pairs (each pair lands in both lists).
  void assign_from_pairs(std::size_t agent_count, std::span<const ClosePair> pairs);

  void reset(std::size_t agent_count) {
    ++generation_;
    agent_count_of_pairs_ = kNotFromPairs;
    begin_.assign(agent_count + 1, 0);
    items_.clear();
    pairs_.clear();
  }
  // Agents must be filled in order 0, 1, 2, ...: push their neighbours, then close them.
  void push(const Neighbour& n) { items_.push_back(n); }
  void close_agent(AgentId agent);  // sorts the agent's neighbours by distance
  std::span<const Neighbour> of(AgentId agent) const {
    return {items_.data() + begin_[agent], items_.data() + begin_[agent + 1]};
  }
  // Every perceived pair once, as (i, j) with i < j and j in i's list, in no particular
  // order: a pass over all pairs need not walk every agent's list.
  std::span<const ClosePair> pairs() const { return pairs_; }
  std::size_t agent_count() const { return begin_.empty() ? 0 : begin_.size() - 1; }
  std::size_t total() const { return items_.size(); }
  // Counts the changes (assign_from_pairs with other pairs than the last, reset): while it
  // stays, so do the lists, and whatever was computed from them only.
  std::uint64_t generation() const { return generation_; }

 private:
  std::uint64_t generation_ = 0;
  // The agent count of the last assign_from_pairs (kNotFromPairs after reset).
  static constexpr std::size_t kNotFromPairs = ~std::size_t{0};
  std::size_t agent_count_of_pairs_ = kNotFromPairs;
  AgentArray<std::uint32_t> begin_;
  AgentArray<Neighbour> items_;
  AgentArray<ClosePair> pairs_;
  AgentArray<AgentId> crowded_;        // agents with two or more neighbours (to sort), and room
  AgentArray<std::uint8_t> resorted_;  // remeasure's marks, all clear between calls

  // assign_from_pairs for the same pairs with some measured anew (true), in place.
  bool remeasure(std::span<const ClosePair> pairs);
};

}  // namespace swarmagg
