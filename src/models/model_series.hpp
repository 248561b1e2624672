#pragma once
// What a model variant predicts, in the shapes the outputs need: rows with the simulation's
// timeseries.csv columns (so model and simulation plot together) and extra tidy values that
// have no timeseries column (partition probabilities, stationary values). A column a model
// does not predict stays empty rather than pretending to be zero.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarmagg {

struct TimeseriesRow {
  int replicate = 0;
  std::int64_t step = 0;
  std::optional<double> noa, searching, waiting, leaving, approaching, largest;
  std::optional<double> creations, growths, dissipations, shrinks, encounters;  // cumulative
};

// The value columns of timeseries.csv, in its order, with the row field holding each.
struct TimeseriesColumn {
  const char* name;
  std::optional<double> TimeseriesRow::*field;
};
inline constexpr TimeseriesColumn kTimeseriesColumns[] = {
    {"noa", &TimeseriesRow::noa},
    {"searching", &TimeseriesRow::searching},
    {"waiting", &TimeseriesRow::waiting},
    {"leaving", &TimeseriesRow::leaving},
    {"approaching", &TimeseriesRow::approaching},
    {"largest", &TimeseriesRow::largest},
    {"creations", &TimeseriesRow::creations},
    {"growths", &TimeseriesRow::growths},
    {"dissipations", &TimeseriesRow::dissipations},
    {"shrinks", &TimeseriesRow::shrinks},
    {"encounters", &TimeseriesRow::encounters},
};

// One tidy value; no step means "stationary" (time-independent).
struct TidyValue {
  std::string quantity;
  std::optional<std::int64_t> step;
  double value = 0.0;
};

struct VariantPrediction {
  std::string model;    // bayindir | soysal
  std::string variant;  // original | collision | original-stochastic | peripheral ...
  bool stochastic = false;  // series holds replicates; model.csv gets their statistics
  std::vector<TimeseriesRow> series;
  std::vector<TidyValue> extra;
};

}  // namespace swarmagg
