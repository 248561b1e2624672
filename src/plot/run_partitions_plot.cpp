// partitions.png: see run_plot.hpp.
#include "analysis/partition_comparison.hpp"
#include "plot/partition_plot.hpp"
#include "plot/run_plot.hpp"

namespace swarmagg {

void draw_run_partitions(const RunFiles& run, const FigureFiles& files) {
  plot_partitions(files, run_title(run) + ": time per partition (mean over replicates)",
                  compare_partitions(run.folder));
}

}  // namespace swarmagg
