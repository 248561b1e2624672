#pragma once
// Reading model.csv (`model,variant,step,time,quantity,value`) back by quantity: a plot
// asks for one quantity's curve per variant, or for every quantity with a prefix
// ("aggregates:" -> the size distribution), variants in file order.
#include <string>
#include <vector>

#include "analysis/csv_table.hpp"

namespace swarmagg {

struct ModelCurve {
  std::string variant;
  std::vector<double> x;  // time, or the quantity's suffix read as a number
  std::vector<double> y;
};

// The time-dependent values of `quantity` (rows with a time), one curve per variant.
std::vector<ModelCurve> model_curves(const CsvTable& model, const std::string& quantity);

// Every "<prefix><number>" quantity (at any one step), x the number, one curve per variant.
std::vector<ModelCurve> model_curves_by_suffix(const CsvTable& model, const std::string& prefix);

}  // namespace swarmagg
