#pragma once
// Figs 7-8: encounters per tu against N or v, simulation mean with its replicate standard
// deviation as error bars, the kinetic prediction and the paper's fitted formula as lines.
#include <vector>

#include "plot/figure_files.hpp"
#include "reproduce/encounter_comparison.hpp"

namespace swarmagg {

enum class EncounterAxis { Agents, Speed };

void plot_encounters(const FigureFiles& files, const std::string& title, EncounterAxis axis,
                     const std::vector<EncounterPoint>& points);

}  // namespace swarmagg
