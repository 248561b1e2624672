#pragma once
// The macroscopic predictions written beside a run (docs/reference/outputs.md): model.csv (tidy,
// every variant) and model-timeseries/<model>-<variant>.csv (the simulation's timeseries.csv
// columns, so model and simulation plot together). Variant files the earlier model.csv of the
// folder lists and this model does not write are removed from model-timeseries/ (no others).
// Each variant is computed while its rows are written (models/pending_variant.hpp), so the
// memory does not grow with the run's length; every file is written atomically, all of
// them once the last variant is through: an error or Ctrl-C leaves the folder's earlier
// model outputs as they were.
#include <filesystem>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "models/model_series.hpp"
#include "models/pending_variant.hpp"

namespace swarmagg {

// Returns each variant with its extra values and, of its rows, those of the last recorded
// step only (what models/predictions.hpp's prediction_summary reads). `show_progress`: a
// progress line on stderr when the computation takes more than a second
// (run/model_progress.hpp); Ctrl-C is checked either way.
std::vector<VariantPrediction> write_model_outputs(const WorldSpec& spec,
                                                   const std::vector<PendingVariant>& variants,
                                                   const std::filesystem::path& out,
                                                   bool show_progress = false);

// model.csv's text alone, made as write_model_outputs makes it, without holding the rows:
// what Python's Run.model_csv returns.
std::string model_csv_text(const WorldSpec& spec, const std::vector<PendingVariant>& variants);

}  // namespace swarmagg
