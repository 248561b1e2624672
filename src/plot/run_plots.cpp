#include "plot/run_plots.hpp"

#include <stdexcept>

#include "controllers/controller_registry.hpp"
#include "plot/gnuplot.hpp"
#include "plot/plot_collection.hpp"

namespace swarmagg {
namespace {

bool always(const RunFiles&) {
  return true;
}

bool forms_aggregates(const RunFiles& run) {
  // The collision check's worlds are about encounters (docs/models.md), not aggregates.
  return controller_rules(run.world).model != ModelFamily::Encounters;
}

bool has_partitions(const RunFiles& run) {
  return run.has_partitions;
}

}  // namespace

const std::vector<RunPlot>& run_plots() {
  static const std::vector<RunPlot> plots{
      {"noa", "NOA over time: mean, 95% band, replicates, model variants", always,
       draw_noa_over_time},
      {"states", "agents per state over time (mean over replicates)", always,
       draw_states_over_time},
      {"sizes", "final aggregate size distribution, with the model's", forms_aggregates,
       draw_final_sizes},
      {"partitions", "Soysal worlds: time per partition, simulation and model variants",
       has_partitions, draw_run_partitions},
  };
  return plots;
}

std::string plots_unavailable_reason() {
  if (gnuplot_available()) return "";
  return "gnuplot is not on PATH (install it with 'sudo apt-get install gnuplot-nox', then "
         "draw them with 'swarmagg plot RUN_DIR')";
}

PlotOutcome draw_run_plots(const std::filesystem::path& run_folder,
                           const std::filesystem::path& out, const PlotSize& size) {
  const RunFiles run = read_run_files(run_folder);
  if (const std::string reason = plots_unavailable_reason(); !reason.empty()) {
    throw std::runtime_error("cannot draw plots: " + reason);
  }
  std::filesystem::create_directories(out / kPlotsFolder);
  PlotCollection batch;
  for (const RunPlot& plot : run_plots()) {
    if (!plot.applies(run)) continue;
    batch.prepare({out / kPlotsFolder, plot.id, size, ".."},
                  [&](const FigureFiles& files) { plot.draw(run, files); });
  }
  return batch.draw();
}

}  // namespace swarmagg
