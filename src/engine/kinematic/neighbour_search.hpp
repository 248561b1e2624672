#pragma once
// The pairs of agents one step needs, found after the previous step: those within the
// sensing radius (what the agents perceive) and those close enough to meet during the next
// step (the guarded-motion solver's candidates). Pairs are searched in sorted strips
// (sorted_strips.hpp); worlds too small for three strips by the arena's pair finder
// (geometry/pair_finder.hpp). Either way a pair is reported as a function of the pair alone:
// i < j and the minimum-image offset from i to j, so results never depend on which search
// found it. Several threads may search strips at once; each fills its own buffers, joined in
// strip order, so the result does not depend on the thread count. The kinematic engine
// searches only every few steps, for a Verlet list (verlet_pairs.hpp).
#include <span>
#include <vector>

#include "control_interface/neighbour_lists.hpp"
#include "engine/kinematic/guarded_motion.hpp"
#include "engine/kinematic/sorted_strips.hpp"
#include "engine/kinematic/step_threads.hpp"
#include "geometry/pair_finder.hpp"

namespace swarmagg {

struct SearchRadii {
  double sensing = 4.0;     // perception: pairs within it become ClosePairs
  double pair_reach = 4.2;  // candidates: pairs within it become CandidatePairs
  bool perception = true;   // false: only candidates are wanted
};

class NeighbourSearch {
 public:
  // Finds the pairs among agents at `positions` (by id).
  void find(const ArenaGeometry& arena, std::span<const Vec2> positions, const SearchRadii& radii,
            StepThreads& threads);

  std::span<const CandidatePair> candidates() const { return candidates_; }
  std::span<const ClosePair> close_pairs() const { return close_; }

 private:
  struct Found {
    AgentArray<CandidatePair> candidates;
    AgentArray<ClosePair> close;
  };

  // Files the pair i < j, `offset` from i to j, by its distance.
  void report(Found& out, std::uint32_t i, std::uint32_t j, Vec2 offset) const;
  void scan_strips(std::size_t agents, StepThreads& threads);
  void scan_task(int task, int tasks);
  void scan_small(const ArenaGeometry& arena, std::span<const Vec2> positions, double reach);
  void join_tasks(int tasks);

  SearchRadii radii_;
  ArenaGeometry arena_{1.0, 1.0, Topology::Torus};
  SortedStrips strips_;
  PairFinder small_world_;
  std::vector<Found> found_;  // per task
  std::span<const CandidatePair> candidates_;
  std::span<const ClosePair> close_;
  AgentArray<CandidatePair> joined_candidates_;
  AgentArray<ClosePair> joined_close_;
};

}  // namespace swarmagg
