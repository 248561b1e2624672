#pragma once
// Where the models start by default (model.initial_state: placement; models/initial_state.hpp):
// the mean aggregates after the first decision of placements drawn as runs draw theirs,
// with the world's own engine and controller. The placements come from a stream of the
// world's seed that no replicate of a run uses, so the models' start is a prediction made
// apart from the run it is compared with. Given positions are a single placement (their
// first decision is certain).
#include <optional>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "models/initial_state.hpp"
#include "models/measured_terms.hpp"
#include "models/model_series.hpp"
#include "models/pending_variant.hpp"

namespace swarmagg {

// Placements drawn for a random placement of `agents` agents: about 2^18 agents in all, from 8
// (large swarms, where one placement already averages over many groups) to 4096 (small ones).
// The start's NOA then carries a standard error of 0.3-1.2 % in the paper's Bayindir worlds;
// in its Soysal worlds, where agents rarely start within s, 0.0018-0.0046 aggregates (8-13 %
// of starts of 0.013-0.088), far below anything the partition chain's errors can show.
int placements_to_sample(int agents);

// The sample (on `threads` threads; the result does not depend on them).
PlacementSample sample_placements(const WorldSpec& world, int threads);

// The sample the world's models need (starts_from_placement_sample), or none.
std::optional<PlacementSample> placement_start(const WorldSpec& world, int threads);

// placement_start for a simulation that has already run: a start that cannot be sampled (one
// of its placements jammed, in a nearly full arena) comes back empty with the reason in `why`
// instead of throwing, so that the run's own outputs are kept.
std::optional<PlacementSample> placement_start_or_reason(const WorldSpec& world, int threads,
                                                         std::string& why);

// The note for rates measured without that start (`why`): their `initial` rows' model values
// come from the second-order formula instead.
std::string second_order_initial_note(const std::string& why);

// One sentence for the user: where the models start, from how many placements.
std::string placement_start_note(const PlacementSample& sample);

// pending_predictions() (models/predictions.hpp) from the world's own start; the variants
// keep what they need of the sample.
std::vector<PendingVariant> pending_world_predictions(const WorldSpec& world,
                                                      const MeasuredTerms* measured, int threads);
// predict() (models/predictions.hpp) from the world's own start.
std::vector<VariantPrediction> predict_world(const WorldSpec& world, const MeasuredTerms* measured,
                                             int threads);

}  // namespace swarmagg
