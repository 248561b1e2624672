#pragma once
// Reading model.csv (`model,variant,step,time,quantity,value`) back by quantity: a plot
// asks for one quantity's curve per variant, or for every quantity with a prefix
// ("aggregates:" -> the size distribution), variants in file order. The file is read row by
// row (a long run's model.csv reaches gigabytes): only the curves asked for are held.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/step_series.hpp"

namespace swarmagg {

struct ModelCurve {
  std::string variant;
  std::vector<double> x;  // time, or the quantity's suffix read as a number
  std::vector<double> y;
};

// The time-dependent values of `quantity` (rows with a time), one curve per variant.
std::vector<ModelCurve> model_curves(const std::filesystem::path& model_csv,
                                     const std::string& quantity, const StepFilter& keep = {});

// Every "<prefix><m>" quantity (at any one step), x the number m, one curve per variant;
// InputError for an m that is not a whole number from 2 to `largest`.
std::vector<ModelCurve> model_curves_by_suffix(const std::filesystem::path& model_csv,
                                               const std::string& prefix, int largest);

}  // namespace swarmagg
