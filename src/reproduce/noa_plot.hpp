#pragma once
// Figs 9-19: NOA over time, box plots across replicates at sampled times (whiskers min/max,
// box quartiles, bar median) with the model variants' expected NOA as curves: Bayindir's
// original in blue, the collision-theory variant in orange (kinetic solid, the paper's fit
// dashed), as the paper colours them.
#include "plot/figure_files.hpp"
#include "reproduce/noa_comparison.hpp"

namespace swarmagg {

inline constexpr int kNoaBoxes = 15;  // sampled times per plot, as legible box plots allow

void plot_noa(const FigureFiles& files, const std::string& title, const NoaComparison& comparison);

}  // namespace swarmagg
