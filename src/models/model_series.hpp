#pragma once
// What a model variant predicts, in the shapes the outputs need: rows with the simulation's
// timeseries.csv columns (so model and simulation plot together) and extra tidy values that
// have no timeseries column (partition probabilities, stationary values). A column a model
// does not predict stays empty rather than pretending to be zero. The models do not tell
// GO, LEAVE and APPROACH apart: their `searching` is every agent outside an aggregate (the
// simulation's searching + leaving + approaching) and `waiting` is N minus that.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarmagg {

struct ModelRow {
  int replicate = 0;
  std::int64_t step = 0;
  std::optional<double> noa, searching, waiting, leaving, approaching, largest;
  std::optional<double> creations, growths, dissipations, shrinks, encounters;  // cumulative
};

// The value columns of timeseries.csv, in its order, with the row field holding each.
struct ModelColumn {
  const char* name;
  std::optional<double> ModelRow::*field;
};
inline constexpr ModelColumn kModelColumns[] = {
    {"noa", &ModelRow::noa},
    {"searching", &ModelRow::searching},
    {"waiting", &ModelRow::waiting},
    {"leaving", &ModelRow::leaving},
    {"approaching", &ModelRow::approaching},
    {"largest", &ModelRow::largest},
    {"creations", &ModelRow::creations},
    {"growths", &ModelRow::growths},
    {"dissipations", &ModelRow::dissipations},
    {"shrinks", &ModelRow::shrinks},
    {"encounters", &ModelRow::encounters},
};

// One tidy value; no step means "stationary" (time-independent).
struct TidyValue {
  std::string quantity;
  std::optional<std::int64_t> step;
  double value = 0.0;
};

// The size distribution a model predicts at the run's last step, as extra values
// "aggregates:<m>" (expected number of aggregates of size m); sizes expected fewer than
// kNegligibleAggregates times are left out, so model.csv does not list N - 1 zeros.
inline constexpr const char* kAggregatesOfSize = "aggregates:";
inline constexpr double kNegligibleAggregates = 1e-6;

struct VariantPrediction {
  std::string model;        // bayindir | soysal
  std::string variant;      // original | collision | original-stochastic | peripheral ...
  bool stochastic = false;  // series holds replicates; model.csv gets their statistics
  bool chosen = false;      // the variant the world's model block names (creation / leaving)
  std::vector<ModelRow> series = {};
  std::vector<TidyValue> extra = {};
};

// Appends the "aggregates:<m>" values at `step` to a variant's `extra`; by_size[m] is the
// expected number of aggregates of size m (indices 0 and 1 ignored).
void add_size_distribution(std::vector<TidyValue>& extra, std::int64_t step,
                           const std::vector<double>& by_size);

}  // namespace swarmagg
