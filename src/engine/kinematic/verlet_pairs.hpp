#pragma once
// The pairs one kinematic step needs (neighbour_search.hpp), found from a Verlet list kept
// over several steps: the pairs within a window wider than the search reach by a skin. Two
// agents come nearer by at most the sum of their moves, so while twice the largest move
// since the list was built fits in the skin, every pair within the reach is listed, and a
// step only measures the listed pairs instead of searching space again.
//
// Each pair is measured exactly as a fresh search measures it (the minimum-image offset from
// the lower id to the higher, tested against the same squared radii), so the pairs found are
// the ones NeighbourSearch finds. Their order differs, which nothing downstream sees: the
// lists are sorted by (distance, id), aggregates are labelled by their lowest member, and
// the guarded motion orders its events by (time, ids, kind) whatever order pairs come in.
#include <cstdint>
#include <span>

#include "control_interface/neighbour_lists.hpp"
#include "core/agent_array.hpp"
#include "engine/kinematic/guarded_motion.hpp"
#include "engine/kinematic/neighbour_search.hpp"
#include "engine/kinematic/step_threads.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

class VerletPairs {
 public:
  // `skin`: how much wider than the reach the list is built (0: searched at every call).
  explicit VerletPairs(double skin) : skin_(skin) {}

  // Finds the candidates among agents at `positions` (by id), every agent having moved at
  // most `moved` since the last call; with radii.perception, rebuilds `lists` from the
  // perceived pairs too (left as they are otherwise; always the same lists).
  // `pairs_moved` false: no agent of a listed pair (paired()) moved since the last call. With
  // the list and the radii kept, every listed pair then measures as it did, bit for bit, so
  // the candidates and lists are left as they are (kept()).
  void find(const ArenaGeometry& arena, std::span<const Vec2> positions, const SearchRadii& radii,
            double moved, StepThreads& threads, NeighbourLists& lists, bool pairs_moved = true);

  // Whether `agent` belongs to a listed pair (any agent, while no list fits the agent count).
  // The flags are found on the first question after a build: a moving world never asks.
  bool paired(std::uint32_t agent) {
    if (agent >= agents_) return true;
    if (!paired_known_) mark_paired();
    return paired_[agent] != 0;
  }
  // Whether the last find measured nothing: its candidates and lists are those of the find
  // before it.
  bool kept() const { return kept_; }

  std::span<const CandidatePair> candidates() const {
    return {candidates_.data(), candidate_count_};
  }
  // How often the list was built since construction (each find builds it or reuses it).
  std::uint64_t builds() const { return builds_; }

 private:
  struct ListedPair {
    std::uint32_t i;  // i < j
    std::uint32_t j;
  };

  // The radii a measurement used (perception: whether it assigned the lists).
  struct Measured {
    double sensing = -1.0;
    double pair_reach = -1.0;
    bool perception = false;
    bool operator==(const Measured&) const = default;
  };

  bool covers(const ArenaGeometry& arena, std::size_t agents, double reach) const;
  void mark_paired();
  void build(const ArenaGeometry& arena, std::span<const Vec2> positions, double reach,
             StepThreads& threads);
  template <bool kPerception>
  void measure(const ArenaGeometry& arena, std::span<const Vec2> positions,
               const SearchRadii& radii);

  double skin_;
  NeighbourSearch search_;
  // The list, by lower id: the pairs within window_ in `arena_` when built, for agents_
  // agents, each of which has moved at most moved_ since.
  ArenaGeometry arena_{1.0, 1.0, Topology::Torus};
  std::size_t agents_ = 0;
  double window_ = -1.0;
  double moved_ = 0.0;
  std::uint64_t builds_ = 0;
  AgentArray<ListedPair> listed_;
  AgentArray<std::uint32_t> first_of_agent_;  // the counting sort's scratch
  AgentArray<std::uint8_t> paired_;           // by agent: in some listed pair
  bool paired_known_ = false;                 // paired_ holds the list's flags
  Measured measured_;                         // by the last measurement (none yet: -1)
  bool kept_ = false;
  // What a step found: the first candidate_count_ and close_count_ entries (the buffers
  // only grow, with a slot to spare for the branch-free writes).
  AgentArray<CandidatePair> candidates_;
  std::size_t candidate_count_ = 0;
  AgentArray<ClosePair> close_;
  std::size_t close_count_ = 0;
};

}  // namespace swarmagg
