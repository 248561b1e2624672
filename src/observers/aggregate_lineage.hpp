#pragma once
// Where each step's aggregates came from. Between two labellings of the agents (the tracker's
// aggregate_of, -1 for agents in no aggregate), each aggregate now and each aggregate before
// are linked when they share a member. An aggregate now that shares no member with one before
// was born; one before that shares none with one now died; one now that holds members of k
// aggregates before is k - 1 merges; one before whose members are in k aggregates now is
// k - 1 splits. So, step by step and exactly,
//   NOA now - NOA before = births - deaths - merges + splits.
// The macroscopic models change the NOA only by creations and dissipations. Births and deaths
// are their counterparts seen in the labels, not the controller's event counts (those differ a
// little: members leaving in one step, a chain falling apart into single agents). Merges and
// splits are what the models leave out: aggregates that grow into one another (a joining agent
// bridging two, bodies shoved together) and aggregates that break apart.
#include <cstdint>
#include <span>
#include <vector>

namespace swarmagg {

struct LineageCounts {
  std::uint64_t births = 0;
  std::uint64_t deaths = 0;
  std::uint64_t merges = 0;
  std::uint64_t splits = 0;
};

class AggregateLineage {
 public:
  // The labelling after the next step (aggregates 0 .. count - 1); the first call counts
  // every aggregate it sees as born.
  void observe(std::span<const std::int32_t> aggregate_of, int count);
  const LineageCounts& counts() const { return counts_; }

 private:
  LineageCounts counts_;
  std::vector<std::int32_t> before_;  // the last labelling
  int count_before_ = 0;
  std::vector<std::uint64_t> links_;  // (aggregate now << 32) | aggregate before, scratch
};

}  // namespace swarmagg
