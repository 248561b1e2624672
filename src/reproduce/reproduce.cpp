#include "reproduce/reproduce.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "analysis/csv_table.hpp"
#include "analysis/csv_text.hpp"
#include "config/world_loader.hpp"
#include "config/world_override.hpp"
#include "controllers/controller_registry.hpp"
#include "output/atomic_file.hpp"
#include "plot/partition_plot.hpp"
#include "rates/rates_csv.hpp"
#include "reproduce/claims.hpp"
#include "reproduce/compaction_effect.hpp"
#include "reproduce/compaction_report.hpp"
#include "reproduce/encounter_plot.hpp"
#include "reproduce/noa_plot.hpp"
#include "reproduce/report.hpp"
#include "reproduce/run_cache.hpp"
#include "reproduce/timeout_series.hpp"

namespace swarmagg {
namespace {

constexpr const char* kPlotFolder = "plots";  // under --out, beside REPORT.md

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A Soysal run's stationarity and NOA / largest-aggregate distributions, for the report.
void add_run_distributions(FigureResult& result, const std::filesystem::path& run) {
  const CsvTable timeseries = read_csv(run / "timeseries.csv");
  const StepSeries noa = read_step_series(timeseries, "noa");
  result.trend = second_half_trend(noa);
  result.noa_distribution = value_distribution(noa);
  result.largest_distribution = value_distribution(read_step_series(timeseries, "largest"));
}

void compare_and_plot(FigureResult& result, const std::filesystem::path& runs,
                      const FigureFiles& files) {
  const PaperFigure& figure = result.figure;
  switch (figure.kind) {
    case FigureKind::EncountersVsCount:
    case FigureKind::EncountersVsSpeed:
      for (std::size_t i = 0; i < result.worlds.size(); ++i) {
        result.encounters.push_back(measure_encounters(result.worlds[i], runs / figure.worlds[i]));
      }
      plot_encounters(files, figure.title,
                      figure.kind == FigureKind::EncountersVsCount ? EncounterAxis::Agents
                                                                   : EncounterAxis::Speed,
                      result.encounters);
      break;
    case FigureKind::Noa:
      result.noa = compare_noa(runs / figure.worlds.front());
      result.rates = read_rates_csv(runs / figure.worlds.front() / "rates.csv");
      result.member_spacing = final_member_spacing(runs / figure.worlds.front());
      plot_noa(files, figure.title, *result.noa);
      break;
    case FigureKind::Partition:
      result.partitions = compare_partitions(runs / figure.worlds.front());
      result.rates = read_rates_csv(runs / figure.worlds.front() / "rates.csv");
      add_run_distributions(result, runs / figure.worlds.front());
      result.member_spacing = final_member_spacing(runs / figure.worlds.front());
      plot_partitions(files, figure.title, *result.partitions);
      break;
  }
}

std::string errors_text(const std::vector<VariantError>& errors, const char* measure) {
  std::string text = std::string(measure);
  for (const VariantError& e : errors) text += " " + e.variant + " " + report_number(e.error);
  return text;
}

std::string errors_text(const FigureResult& r) {
  if (r.noa) return errors_text(r.noa->errors, "NOA RMSE");
  if (r.partitions) return errors_text(r.partitions->errors, "TV distance");
  return "";
}

std::string summary_line(const FigureResult& r, const FigureResult* compaction_off) {
  std::string line = "Fig " + r.figure.figures + " (" + r.figure.id +
                     "): " + std::to_string(r.worlds.size()) + " world(s), " +
                     std::to_string(r.reused) + " reused, " + report_number(r.wall_seconds) +
                     " s; ";
  line += errors_text(r);
  if (!r.encounters.empty()) {
    double deviation = 0.0;
    for (const EncounterPoint& p : r.encounters)
      deviation += std::abs(p.simulated - p.kinetic) / p.kinetic;
    line += "mean |deviation| from kinetic theory " +
            report_number(100 * deviation / r.encounters.size()) + " %";
  }
  if (compaction_off) {
    line += "; compaction off (" + report_number(compaction_off->wall_seconds) +
            " s): " + errors_text(*compaction_off);
  }
  return line;
}

// One arm of the reproduction: the folder that holds its runs/ and plots/, and what it
// changes in every world after reproduce_overrides.
struct Arm {
  std::filesystem::path root;
  std::vector<WorldOverride> overrides;
};

FigureResult reproduce_figure(const ReproduceOptions& options, const PaperFigure& figure,
                              const Arm& arm) {
  const auto start = Clock::now();
  FigureResult result;
  result.figure = figure;
  const std::filesystem::path runs = arm.root / "runs";
  RunOptions run_options;
  run_options.threads = options.threads;
  run_options.progress = options.progress;
  for (const std::string& name : figure.worlds) {
    const std::string path = (options.worlds / (name + ".yaml")).string();
    WorldSpec world = load_world(path);
    for (const WorldOverride& o : reproduce_overrides(options, world)) apply_override(world, o);
    for (const WorldOverride& o : arm.overrides) apply_override(world, o);
    check_world(world);
    result.reused += ensure_run(world, runs / name, run_options) ? 1 : 0;
    result.worlds.push_back(std::move(world));
  }
  const FigureFiles files{arm.root / kPlotFolder, figure.id, options.plot_size, ""};
  std::filesystem::create_directories(files.folder);
  compare_and_plot(result, runs, files);
  // Relative to the report, which sits in options.out.
  result.plot = (arm.root.lexically_relative(options.out) / kPlotFolder / files.png_name())
                    .lexically_normal()
                    .generic_string();
  result.wall_seconds = seconds_since(start);
  return result;
}

// Compaction changes the Bayindir and Soysal experiments whose worlds compact; the collision
// checks have no waiting agents, and a world already run without compaction has no other arm.
bool compaction_applies(const FigureResult& result) {
  const FigureKind kind = result.figure.kind;
  if (kind != FigureKind::Noa && kind != FigureKind::Partition) return false;
  return std::all_of(result.worlds.begin(), result.worlds.end(),
                     [](const WorldSpec& w) { return controller_rules(w).compacts; });
}

Arm compaction_off_arm(const ReproduceOptions& options) {
  return {options.out / kCompactionOffFolder,
          {typed_override("controller.compaction.enabled", false, "reproduce (compaction off)")}};
}

// The compaction-off result of `figure`, if that arm ran.
const FigureResult* compaction_off_of(const FigureResult& figure,
                                      const std::vector<FigureResult>& off) {
  for (const FigureResult& o : off) {
    if (o.figure.id == figure.figure.id) return &o;
  }
  return nullptr;
}

// The figures with each compaction-off result in place of its compaction-on one, so the
// claims can be checked as they stand without compaction.
std::vector<FigureResult> with_compaction_off(std::vector<FigureResult> figures,
                                              const std::vector<FigureResult>& off) {
  for (FigureResult& figure : figures) {
    if (const FigureResult* o = compaction_off_of(figure, off)) figure = *o;
  }
  return figures;
}

std::vector<CompactionEffect> compaction_effects(const std::vector<FigureResult>& figures,
                                                 const std::vector<FigureResult>& off) {
  std::vector<CompactionEffect> effects;
  for (const FigureResult& figure : figures) {
    if (const FigureResult* o = compaction_off_of(figure, off))
      effects.push_back(compaction_effect(figure, *o));
  }
  return effects;
}

}  // namespace

std::vector<WorldOverride> reproduce_overrides(const ReproduceOptions& options,
                                               const WorldSpec& world) {
  std::vector<WorldOverride> overrides;
  if (options.quick) {
    overrides.push_back(typed_override("run.replicates", kQuickReplicates, "--quick"));
    overrides.push_back(
        typed_override("run.duration", world.run.duration / kQuickDurationDivisor, "--quick"));
  }
  if (!options.engine.empty()) {
    overrides.push_back(typed_override("engine.type", options.engine, "--engine"));
  }
  for (WorldOverride& o : parse_overrides(options.overrides)) overrides.push_back(std::move(o));
  return overrides;
}

ReproduceOutcome reproduce(const ReproduceOptions& options, std::ostream& summary) {
  const auto start = Clock::now();
  ReproduceOutcome outcome;
  for (const PaperFigure& figure : select_worlds(paper_figures(), options.only)) {
    outcome.figures.push_back(reproduce_figure(options, figure, Arm{options.out, {}}));
    const FigureResult* off = nullptr;
    if (compaction_applies(outcome.figures.back())) {
      outcome.compaction_off.push_back(
          reproduce_figure(options, figure, compaction_off_arm(options)));
      off = &outcome.compaction_off.back();
    }
    summary << summary_line(outcome.figures.back(), off) << std::endl;
  }
  std::vector<TimeoutPoint> series;
  if (timeout_series_selected(options)) {
    series = run_timeout_series(options);
    write_file_atomic(options.out / (std::string(kTimeoutFolder) + ".csv"),
                      timeout_series_csv(series));
    plot_timeout_series(options.out / kPlotFolder, options.plot_size, series);
    for (const TimeoutPoint& p : series) {
      summary << "timeout series " << p.world << " timeout " << report_number(p.leave_timeout)
              << (p.reused ? " (reused)" : "") << ", " << report_number(p.wall_seconds) << " s; "
              << errors_text(p.comparison.errors, "TV distance") << std::endl;
    }
  }
  outcome.wall_seconds = seconds_since(start);
  std::string mode = options.quick ? "quick" : "full";
  for (const std::string& o : options.overrides) mode += ", --set " + o;
  for (const std::string& o : options.only) mode += ", --only " + o;
  const ReportContext context{mode, options.engine.empty() ? "as in each world" : options.engine,
                              outcome.wall_seconds, series};
  outcome.report = options.out / "REPORT.md";
  const std::vector<ClaimCheck> claims = check_claims(outcome.figures);
  const std::vector<CompactionEffect> effects =
      compaction_effects(outcome.figures, outcome.compaction_off);
  write_file_atomic(options.out / kCompactionCsv, compaction_csv(effects));
  write_file_atomic(outcome.report,
                    report_markdown(context, outcome.figures, claims) + "\n" +
                        compaction_section(effects, claims,
                                           check_claims(with_compaction_off(
                                               outcome.figures, outcome.compaction_off)),
                                           kCompactionOffFolder));
  return outcome;
}

}  // namespace swarmagg
