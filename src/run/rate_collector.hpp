#pragma once
// Measured rates of a run (docs/models.md): an observer per replicate feeds a RateRecorder every
// step, and the collector merges the replicates' tallies. Each observer writes only its own
// replicate's slot, so replicates may run in any threads; the merged sums are whole numbers,
// identical for any thread count.
#include <memory>
#include <optional>
#include <vector>

#include "config/world_spec.hpp"
#include "rates/rate_tally.hpp"
#include "run/replicate_observer.hpp"

namespace swarmagg {

class RateCollector {
 public:
  explicit RateCollector(const WorldSpec& spec);

  // The observer of replicate `index`; it stores the replicate's tally here on finish().
  std::unique_ptr<ReplicateObserver> observer(int index);
  // Every finished replicate's tally, merged.
  RateTally total() const;

 private:
  const WorldSpec& spec_;
  std::vector<std::optional<RateTally>> tallies_;
};

// Both factories' observers on every replicate (either may be empty or return nullptr).
ObserverFactory both_observers(ObserverFactory first, ObserverFactory second);

}  // namespace swarmagg
