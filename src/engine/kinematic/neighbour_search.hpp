#pragma once
// The pairs of agents one step needs, found after the previous step: those within the
// sensing radius (what the agents perceive) and those close enough to meet during the next
// step (the guarded-motion solver's candidates). Pairs are searched in sorted strips
// (sorted_strips.hpp) and reported as the reference grid would (pair_convention.hpp); worlds
// too small for three strips or three grid cells along an axis are searched by the
// reference grid itself (uniform_grid.hpp). Several threads may search strips at once; each fills
// its own buffers, joined in strip order, so the result does not depend on the thread count.
#include <span>
#include <vector>

#include "engine/kinematic/guarded_motion.hpp"
#include "engine/kinematic/pair_convention.hpp"
#include "engine/kinematic/sorted_strips.hpp"
#include "engine/kinematic/step_threads.hpp"
#include "engine/kinematic/uniform_grid.hpp"
#include "control_interface/neighbour_lists.hpp"

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
  struct Plan {
    double reach = 0.0;
    double min_cell = 0.0;  // of the reference grid
    double window = 0.0;    // of the strips
    bool strips = false;    // false: the reference grid searches
  };
  Plan plan(const ArenaGeometry& arena, std::size_t agents, const SearchRadii& radii);
  void scan(const Plan& plan, std::size_t agents, StepThreads& threads);

  struct Found {
    AgentArray<CandidatePair> candidates;
    AgentArray<ClosePair> close;
  };

  void scan_grid(const ArenaGeometry& arena, std::span<const Vec2> positions, double min_cell,
                 double reach);
  void scan_strips(double reach, StepThreads& threads);
  void scan_task(int task, int tasks, double reach);
  void join_tasks(int tasks);

  SearchRadii radii_;
  PairConvention convention_;
  SortedStrips strips_;
  UniformGrid grid_;
  std::vector<Found> found_;  // per task
  std::span<const CandidatePair> candidates_;
  std::span<const ClosePair> close_;
  AgentArray<CandidatePair> joined_candidates_;
  AgentArray<ClosePair> joined_close_;
};

}  // namespace swarmagg
