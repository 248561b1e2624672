#pragma once
// `swarmagg reproduce`: runs every world of worlds/paper/ (or reuses its complete run) into
// <out>/runs/<world>/ with the model outputs beside it, compares each experiment with the
// models, draws one PNG per paper figure into <out>/plots/ and writes <out>/REPORT.md.
// --quick is the same path with fewer replicates and shorter runs, applied as overrides.
// Every Bayindir and Soysal experiment whose world compacts (docs/controllers.md, the default) runs
// a second time with controller.compaction.enabled=false into <out>/compaction-off/{runs, plots}/;
// the report sets the two side by side and <out>/compaction.csv holds the numbers. Then the
// leave-timeout series (reproduce/timeout_series.hpp) runs into <out>/timeout-series/.
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "config/world_override.hpp"
#include "plot/png_terminal.hpp"
#include "rates/rate_outputs.hpp"
#include "reproduce/figure_result.hpp"

namespace swarmagg {

struct ReproduceOptions {
  std::filesystem::path out = "reproduce";
  std::filesystem::path worlds = "worlds/paper";
  bool quick = false;
  std::string engine;                  // empty: the worlds' own engine
  int threads = 0;                     // 0: the machine's cores
  std::vector<std::string> only;       // keep worlds whose name contains one of these
  std::vector<std::string> overrides;  // key.path=value, after the quick ones
  bool progress = false;               // run progress on stderr (only shown on a terminal)
  bool run_plots = false;              // draw each run's rate plots, not only their scripts
  // Run length (tu) of the leave-timeout series (reproduce/timeout_series.hpp); unset: the
  // paper worlds' own. --quick divides it like every run length.
  std::optional<double> timeout_duration;
  PlotSize plot_size;
};

// Quick mode: replicates and run length divided so that every world together runs in
// well under a minute, still long enough to show each curve's shape.
inline constexpr int kQuickReplicates = 3;
inline constexpr double kQuickDurationDivisor = 25.0;

// How the runs' rate plots are written under `options` (--run-plots draws them).
RatePlots run_rate_plots(const ReproduceOptions& options);

// The overrides reproduce applies to a world: quick ones, then the engine, then `overrides`.
std::vector<WorldOverride> reproduce_overrides(const ReproduceOptions& options,
                                               const WorldSpec& world);

// Under --out: the compaction-off arm's runs/ and plots/, and the on/off table.
inline constexpr const char* kCompactionOffFolder = "compaction-off";
inline constexpr const char* kCompactionCsv = "compaction.csv";

struct ReproduceOutcome {
  std::vector<FigureResult> figures;         // every world as it says (compaction on)
  std::vector<FigureResult> compaction_off;  // the NOA and partition figures, compaction off
  std::filesystem::path report;
  double wall_seconds = 0.0;
};

// Writes one summary line per figure to `summary` as it completes.
ReproduceOutcome reproduce(const ReproduceOptions& options, std::ostream& summary);

}  // namespace swarmagg
