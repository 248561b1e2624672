#pragma once
// Every macroscopic prediction that applies to a world (docs/models.md): bayindir and collision
// controllers get the Bayindir model, variants `original` and `collision` (expected values)
// and `original-stochastic`, `collision-stochastic` (model.stochastic_replicates seeded
// replicates); soysal controllers get the partition model, variants `original` and
// `peripheral`. Each variant reads the same WorldSpec the simulator runs; the ones the
// world's model block names (model.creation, model.leaving) are marked `chosen`.
// All of them start from the state after the first decision (model.initial_state).
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "models/initial_state.hpp"
#include "models/measured_terms.hpp"
#include "models/model_series.hpp"
#include "models/pending_variant.hpp"

namespace swarmagg {

// Worlds whose aggregates lose agents also get the `returns` variant (bayindir `returns` and
// `returns-stochastic`, soysal `returns`; models/returns_rates.hpp), and every expected-value
// variant carries its noise floor (models/noise_floor.hpp) as an extra value.
// Every variant starts where model.initial_state says (models/initial_state.hpp; `sample`
// must be given when starts_from_placement_sample(world)). With
// `measured` terms (docs/models.md) the `measured` variants are added too (bayindir `measured` and
// `measured-stochastic`, soysal `measured`; models/measured_rates.hpp).
// None is computed yet: each is walked while its outputs are written (run/model_outputs.hpp),
// so a long run's rows are never all held. Each holds what it needs (rates, start, grid):
// `measured` and `sample` may go.
std::vector<PendingVariant> pending_predictions(const WorldSpec& world,
                                                const MeasuredTerms* measured = nullptr,
                                                const PlacementSample* sample = nullptr);

// The same variants computed, each with every row held (for callers that want the rows: the
// live view, the Python module's model.csv text, tests).
std::vector<VariantPrediction> predict(const WorldSpec& world,
                                       const MeasuredTerms* measured = nullptr,
                                       const PlacementSample* sample = nullptr);

// Throws the InputError predict() would throw for the world's own rates (per-step
// probabilities above 1, say), at once: callers check before costly preparations.
void check_predictable(const WorldSpec& world);

// Why model.csv lists no variant, for a controller no macroscopic model describes; empty
// for the others.
std::string no_model_note(const WorldSpec& world);

// Where the world departs from the models' assumptions, one sentence each.
std::vector<std::string> model_caveats(const WorldSpec& world);
// model_caveats without those every world of its model family shares (no LEAVE timeout in the
// models): what a run of this world should say beside its model errors.
std::vector<std::string> world_caveats(const WorldSpec& world);

// One line per variant: the final expected NOA and, for the partition model, the most
// likely stationary partition.
std::string prediction_summary(const VariantPrediction& prediction);

}  // namespace swarmagg
