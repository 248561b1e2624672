#pragma once
// Model variants drawn over a run's simulation: writes <id>-<part>.csv beside the script
// (x, then one column per variant; `missing` where a variant has no value at that x) and
// returns the plot clauses that draw it, each starting with ", \" so they append to a plot
// command. A variant keeps its colour from variant_colours.hpp; stochastic variants
// ("<name>-stochastic", the mean of the model's replicates) are dashed in their base
// variant's colour. Returns "" and writes nothing when there are no curves.
#include <cmath>
#include <string>
#include <vector>

#include "analysis/model_table.hpp"
#include "plot/figure_files.hpp"

namespace swarmagg {

std::string model_curve_lines(const std::vector<ModelCurve>& curves, const FigureFiles& files,
                              const std::string& part, const std::string& style = "lines lw 2",
                              double missing = std::nan(""));

}  // namespace swarmagg
