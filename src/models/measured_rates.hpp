#pragma once
// The `measured` model variants (docs/models.md): the same model equations fed with the terms a
// simulation measured. Bayindir: creation per searcher pair and growth per (searcher,
// size-m aggregate) pair; Soysal: pair-up P_e(1) and join P_e(i), the same measurements.
// A term not measured (fewer than the events an estimate needs, or sizes the runs never
// held) keeps the model's own value: creation from model.creation, growth from docs/models.md /
// 5.3, leaving from Bayindir's p min(m, periph(m)) or Soysal's model.leaving variant.
// Agents leave at the measured LEAVE attempt rate per size times the fraction that does not
// return, and join at the measured rate of new joins (joins that are not returns): a return
// is neither a loss nor a new encounter (docs/models-returns.md).
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "models/bayindir_rates.hpp"
#include "models/measured_terms.hpp"
#include "models/model_series.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {

BayindirRates measured_bayindir_rates(const WorldSpec& world, const MeasuredTerms& terms);
SoysalRates measured_soysal_rates(const WorldSpec& world, const MeasuredTerms& terms);

// Tidy values that say which terms of a measured variant were measured and which came from
// the model: `terms:creation_measured` (0 or 1), `terms:growth_sizes_measured` and, when
// the world leaves, `terms:leave_sizes_measured` (counts of sizes).
std::vector<TidyValue> measured_term_notes(const WorldSpec& world, const MeasuredTerms& terms);

// Throws InputError for terms no run of `world` can measure: more than one pair-up per
// searcher pair, or join per searcher and aggregate, in a step of dt; more LEAVE attempts per
// step than an aggregate has members; under model.initial_state: measured, a start with
// aggregates larger than the world or holding more agents than it has. Finite but impossible
// rates (hand-edited, or measured in a world with another dt) would drive the expected model
// below zero agents, to NaN.
void check_measured_terms(const WorldSpec& world, const MeasuredTerms& terms);

// The same in words, one sentence, for the command line and rates.json.
std::string measured_variant_note(const WorldSpec& world, const MeasuredTerms& terms);

}  // namespace swarmagg
