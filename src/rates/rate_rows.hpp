#pragma once
// The measured terms of docs/models.md as rows: one per term (and size), each with its estimate
// and what every model variant says the term is. Terms:
//  - creation (Bayindir and collision worlds) / pairup (Soysal): creations per searcher pair
//    per tu; models: original 2 sqrt 2 s v / A, collision 2 kappa s v / A (8 s v / (pi A)
//    kinetic), Soysal's P_e(1) / dt;
//  - growth / join, by the size m joined: growths per searcher per size-m aggregate per tu;
//    models: 2 rho_m v / A (docs/models.md), Soysal's P_e(m) / dt;
//  - initial, by size m: aggregates of size m right after the first decision per replicate
//    (exposure: replicates), against the models' start (models/initial_state.hpp).
//  - attempt / escape, by the size m left: LEAVE attempts (escapes: attempts that ended
//    with no waiting member of the aggregate left within s) per size-m aggregate per tu;
//    models: attempts m P_l(m) / dt, escapes the variant's loss (Bayindir p min(m,
//    periph(m)), Soysal L(m)).
//  - join_new, by the size m joined: joins that are not returns, per searcher (away agents
//    left out) per size-m aggregate per tu; models as growth;
//  - return, by the size m left: the fraction of attempts that came back, of those whose
//    return window closed within the run (binomial interval);
//    model: the returns variant's q over every attempt (models/return_probability.hpp);
//  - return_time, by the size m left: the mean time away of a return in tu (no model);
//  - radius and rim, by size m: the aggregates' mean outer radius and rim count.
#include <optional>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "models/initial_state.hpp"
#include "models/measured_terms.hpp"
#include "rates/poisson_interval.hpp"
#include "rates/rate_tally.hpp"

namespace swarmagg {

struct ModelTerm {
  std::string model;    // bayindir | soysal
  std::string variant;  // original | collision | peripheral
  double rate = 0.0;    // in the row's unit
};

struct RateRow {
  std::string term;
  std::optional<int> size = {};  // empty where size does not apply
  RateEstimate estimate = {};
  std::vector<ModelTerm> models = {};  // one per model variant that predicts the term
};

// The `initial` rows' model value is the models' start: `placement_start` when the models
// start from a sample of placements (run/placement_sample.hpp), else the second-order
// formula (random placements only).
// Every term a rates.csv of this version can hold (the `term` column; rates-<term>.png).
inline constexpr const char* kRateTerms[] = {"creation",    "pairup",  "growth", "join",
                                             "join_new",    "attempt", "escape", "return",
                                             "return_time", "initial", "radius", "rim"};

std::vector<RateRow> measured_rate_rows(const WorldSpec& world, const RateTally& tally,
                                        const PlacementSample* placement_start = nullptr);

// The terms a measured model variant uses: rates with enough events, and the measured
// initial state (events / exposure, whatever the count: a mean count of 0 is a measurement).
MeasuredTerms measured_terms(const std::vector<RateRow>& rows);

}  // namespace swarmagg
