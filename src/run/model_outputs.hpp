#pragma once
// The macroscopic predictions written beside a run (docs/reference/outputs.md): model.csv (tidy,
// every variant) and model-timeseries/<model>-<variant>.csv (the simulation's timeseries.csv
// columns, so model and simulation plot together). Variant files the earlier model.csv of the
// folder lists and this model does not write are removed from model-timeseries/ (no others).
#include <filesystem>
#include <vector>

#include "config/world_spec.hpp"
#include "models/model_series.hpp"

namespace swarmagg {

void write_model_outputs(const WorldSpec& spec, const std::vector<VariantPrediction>& predictions,
                         const std::filesystem::path& out);

}  // namespace swarmagg
