#include "engine/kinematic/verlet_pairs.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

// How many pairs ahead the measuring pass requests the higher agent's position: enough to
// cover a miss to memory with the work of the pairs in between, which is little (16 left
// 43 % of the pass waiting on those reads at 10^6 agents).
constexpr std::size_t kPairsPrefetchedAhead = 64;

// Moves and distances carry rounding errors of a few ulps of the coordinates; the list is
// trusted only while this much more than twice the moves fits in the skin as well.
double rounding_slack(const ArenaGeometry& arena) {
  return 1e-9 * (1.0 + arena.width() + arena.height());
}

bool same_arena(const ArenaGeometry& a, const ArenaGeometry& b) {
  return a.width() == b.width() && a.height() == b.height() && a.torus() == b.torus();
}

// Grown to at least `size`, by half again so that a slowly rising count reallocates
// rarely; never shrunk.
template <typename T>
void grow_to(AgentArray<T>& buffer, std::size_t size) {
  if (buffer.size() < size) buffer.resize(size + size / 2);
}

}  // namespace

bool VerletPairs::covers(const ArenaGeometry& arena, std::size_t agents, double reach) const {
  return window_ >= 0.0 && agents == agents_ && same_arena(arena, arena_) &&
         reach + 2.0 * moved_ + rounding_slack(arena) <= window_;
}

void VerletPairs::find(const ArenaGeometry& arena, std::span<const Vec2> positions,
                       const SearchRadii& radii, double moved, StepThreads& threads,
                       NeighbourLists& lists, bool pairs_moved) {
  const bool perception = radii.perception && radii.sensing > 0.0;
  const double reach = std::max(perception ? radii.sensing : 0.0, radii.pair_reach);
  moved_ += moved;
  const bool rebuilt = !covers(arena, positions.size(), reach);
  if (rebuilt) build(arena, positions, reach, threads);
  const Measured wanted{radii.sensing, radii.pair_reach, perception};
  kept_ = !rebuilt && !pairs_moved && wanted == measured_;
  if (kept_) return;
  measured_ = wanted;
  if (!perception) return measure<false>(arena, positions, radii);
  measure<true>(arena, positions, radii);
  lists.assign_from_pairs(positions.size(), {close_.data(), close_count_});
}

// The pairs within the reach plus the skin, from one search, put in order of their lower id
// by a counting sort, so that the measuring pass reads the lower agent's position in order.
void VerletPairs::build(const ArenaGeometry& arena, std::span<const Vec2> positions, double reach,
                        StepThreads& threads) {
  arena_ = arena;
  agents_ = positions.size();
  window_ = reach + skin_;
  moved_ = 0.0;
  ++builds_;
  SearchRadii wide;
  wide.pair_reach = window_;
  wide.perception = false;
  search_.find(arena, positions, wide, threads);
  const std::span<const CandidatePair> pairs = search_.candidates();
  first_of_agent_.assign(agents_ + 1, 0u);
  for (const CandidatePair& p : pairs) ++first_of_agent_[p.i + 1];
  for (std::size_t a = 0; a < agents_; ++a) first_of_agent_[a + 1] += first_of_agent_[a];
  if (listed_.capacity() < pairs.size()) listed_.reserve(2 * pairs.size());
  listed_.resize(pairs.size());
  for (const CandidatePair& p : pairs) listed_[first_of_agent_[p.i]++] = {p.i, p.j};
  paired_known_ = false;
  // Each step finds at most every listed pair, and writes one slot more.
  grow_to(candidates_, pairs.size() + 1);
  grow_to(close_, pairs.size() + 1);
}

void VerletPairs::mark_paired() {
  paired_.assign(agents_, 0);
  for (const ListedPair& p : listed_) paired_[p.i] = paired_[p.j] = 1;
  paired_known_ = true;
}

// Every listed pair, measured from its lower id: a candidate when within the pair reach, a
// perceived pair when within the sensing radius. Whether a pair lies within a radius is a
// coin toss to the branch predictor: each is written to the next slot and kept by counting.
template <bool kPerception>
void VerletPairs::measure(const ArenaGeometry& arena, std::span<const Vec2> positions,
                          const SearchRadii& radii) {
  const double sensing2 = radii.sensing * radii.sensing;
  const double reach2 = radii.pair_reach * radii.pair_reach;
  const Vec2* position = positions.data();
  const ListedPair* listed = listed_.data();
  const std::size_t count = listed_.size();
  CandidatePair* candidate = candidates_.data();
  ClosePair* close = close_.data();
  std::size_t candidates = 0, perceived = 0;
  for (std::size_t k = 0; k < count; ++k) {
    __builtin_prefetch(position + listed[std::min(k + kPairsPrefetchedAhead, count - 1)].j);
    const std::uint32_t i = listed[k].i, j = listed[k].j;
    const Vec2 offset = arena.displacement(position[i], position[j]);
    const double d2 = norm2(offset);
    candidate[candidates] = {i, j, offset};
    candidates += static_cast<std::size_t>(d2 <= reach2);
    if constexpr (kPerception) {
      close[perceived] = {i, j, offset, std::sqrt(d2)};
      perceived += static_cast<std::size_t>(d2 <= sensing2);
    }
  }
  candidate_count_ = candidates;
  close_count_ = perceived;
}

}  // namespace swarmagg
