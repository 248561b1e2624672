#pragma once
// What a merge tells the user about the earlier merge's files it removed (`merge`, and `sweep`
// when it merges itself), so that a plot or table that vanished is never a surprise.
#include <string>

#include "sweep/sweep_merge.hpp"

namespace swarmagg::cli {

// The lines naming the removed files and, when sweep plots were among them and were not drawn
// again (`plots_drawn` false), the command that draws them; empty when nothing was removed.
std::string merge_removals_text(const MergeReport& report, const std::string& out,
                                bool plots_drawn);

}  // namespace swarmagg::cli
