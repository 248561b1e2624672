#include "reproduce/reproduce.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "analysis/csv_table.hpp"
#include "analysis/csv_text.hpp"
#include "config/world_loader.hpp"
#include "config/world_override.hpp"
#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
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
#include "run/parallel_for.hpp"

namespace swarmagg {
namespace {

// The message for --only patterns that no paper world's name contains, naming the worlds.
std::string no_world_selected(const std::vector<std::string>& patterns) {
  std::string asked, worlds;
  for (const std::string& p : patterns) asked += (asked.empty() ? "'" : ", '") + p + "'";
  for (const PaperFigure& figure : paper_figures()) {
    for (const std::string& world : figure.worlds) worlds += (worlds.empty() ? "" : ", ") + world;
  }
  return "--only: no paper world's name contains " + asked + "; the worlds are " + worlds +
         ", and " + kTimeoutFolder + " selects the leave-timeout series";
}

constexpr const char* kPlotFolder = "plots";  // under --out, beside REPORT.md

// A folder reproduce may write into: missing, empty but for hidden temporaries, or a
// reproduction's own, even one stopped early (its report, or the runs of either arm or of
// the leave-timeout series, which a later reproduction reuses). Anything else (a run, a
// comparison, a sweep, your own files) would get a report written among its files, and a
// run's plots/ filled with figures that are not its own. Other commands' marks come first: a
// sweep's folder holds a runs/ too.
void check_is_a_reproductions_folder(const std::filesystem::path& out) {
  std::error_code missing;
  for (const char* other :
       {"world.resolved.yaml", "compare.json", "sweep.json", "sweep_summary.csv"}) {
    if (!std::filesystem::exists(out / other, missing)) continue;
    throw InputError(out.string() + "/ holds " + other + ", another command's output: a " +
                     "reproduction would write its report and plots/ among its files; use --out "
                     "DIR for the reproduction");
  }
  for (const char* own : {"REPORT.md", "runs", "compaction-off", kTimeoutFolder}) {
    if (std::filesystem::exists(out / own, missing)) return;
  }
  for (const auto& entry : std::filesystem::directory_iterator(out, missing)) {
    if (entry.path().filename().string().starts_with(".")) continue;
    throw InputError(out.string() + "/ holds files but no reproduction (no REPORT.md or runs/): " +
                     "a reproduction would write its report and plots/ among them; use --out "
                     "DIR for the reproduction");
  }
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A Soysal run's stationarity and NOA / largest-aggregate distributions, for the report.
void add_run_distributions(FigureResult& result, const std::filesystem::path& run) {
  const std::vector<StepSeries> series =
      read_step_series(run / "timeseries.csv", std::vector<std::string>{"noa", "largest"});
  result.trend = second_half_trend(series[0]);
  result.noa_distribution = value_distribution(series[0]);
  result.largest_distribution = value_distribution(series[1]);
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
      result.summary = run_summary_facts(runs / figure.worlds.front());
      plot_noa(files, figure.title, *result.noa);
      break;
    case FigureKind::Partition:
      result.partitions = compare_partitions(runs / figure.worlds.front());
      result.rates = read_rates_csv(runs / figure.worlds.front() / "rates.csv");
      add_run_distributions(result, runs / figure.worlds.front());
      result.summary = run_summary_facts(runs / figure.worlds.front());
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

// The figure's worlds as this arm runs them.
std::vector<WorldSpec> figure_worlds(const ReproduceOptions& options, const PaperFigure& figure,
                                     const Arm& arm) {
  std::vector<WorldSpec> worlds;
  for (const std::string& name : figure.worlds) {
    WorldSpec world = load_world((options.worlds / (name + ".yaml")).string());
    for (const WorldOverride& o : reproduce_overrides(options, world)) apply_override(world, o);
    for (const WorldOverride& o : arm.overrides) apply_override(world, o);
    check_world(world);
    worlds.push_back(std::move(world));
  }
  return worlds;
}

FigureResult reproduce_figure(const ReproduceOptions& options, const PaperFigure& figure,
                              const Arm& arm, const RunOptions& run_options) {
  const auto start = Clock::now();
  FigureResult result;
  result.figure = figure;
  const std::filesystem::path runs = arm.root / "runs";
  result.worlds = figure_worlds(options, figure, arm);
  for (std::size_t i = 0; i < result.worlds.size(); ++i) {
    result.reused +=
        ensure_run(result.worlds[i], runs / figure.worlds[i], run_options, run_rate_plots(options))
            ? 1
            : 0;
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
bool compaction_applies(const PaperFigure& figure, const std::vector<WorldSpec>& worlds) {
  if (figure.kind != FigureKind::Noa && figure.kind != FigureKind::Partition) return false;
  return std::all_of(worlds.begin(), worlds.end(),
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

// One unit of reproduce's work for one of its threads: an arm of a figure, or a point of
// the leave-timeout series; `index` is the figure's or the point's.
struct ReproduceJob {
  std::size_t index = 0;
  bool compaction_off = false;
  std::optional<TimeoutRun> timeout = std::nullopt;
  double agent_steps = 0.0;  // what it will simulate, to hand out the longest jobs first
};

double agent_steps(const WorldSpec& world) {
  return static_cast<double>(world.robots.count) * world.run.duration / world.engine.dt *
         world.run.replicates;
}

double agent_steps(const std::vector<WorldSpec>& worlds) {
  double total = 0.0;
  for (const WorldSpec& world : worlds) total += agent_steps(world);
  return total;
}

// Every figure's arms and every timeout point, longest first: with the longest last, one
// thread would finish it alone while the others wait.
std::vector<ReproduceJob> reproduce_jobs(const ReproduceOptions& options,
                                         const std::vector<PaperFigure>& figures,
                                         const std::vector<TimeoutRun>& timeouts) {
  std::vector<ReproduceJob> jobs;
  for (std::size_t f = 0; f < figures.size(); ++f) {
    const std::vector<WorldSpec> worlds = figure_worlds(options, figures[f], Arm{options.out, {}});
    jobs.push_back({.index = f, .agent_steps = agent_steps(worlds)});
    if (compaction_applies(figures[f], worlds)) {
      jobs.push_back({.index = f,
                      .compaction_off = true,
                      .agent_steps = agent_steps(
                          figure_worlds(options, figures[f], compaction_off_arm(options)))});
    }
  }
  for (std::size_t t = 0; t < timeouts.size(); ++t) {
    if (is_paper_run(options, timeouts[t])) continue;  // after the figures: see reproduce()
    jobs.push_back({.index = t,
                    .timeout = timeouts[t],
                    .agent_steps = agent_steps(timeout_world(options, timeouts[t]))});
  }
  std::stable_sort(jobs.begin(), jobs.end(), [](const ReproduceJob& a, const ReproduceJob& b) {
    return a.agent_steps > b.agent_steps;
  });
  return jobs;
}

// Jobs run side by side, one thread each, as long as there are enough jobs for the threads;
// a lone job gets them all for its replicates.
struct ThreadSplit {
  int jobs_at_once = 1;
  int per_job = 1;
};

ThreadSplit split_threads(int requested, std::size_t jobs) {
  const int threads = requested > 0
                          ? requested
                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int at_once =
      static_cast<int>(std::clamp<std::size_t>(jobs, 1, static_cast<std::size_t>(threads)));
  return {at_once, std::max(1, threads / at_once)};
}

std::string timeout_line(const TimeoutPoint& p) {
  std::ostringstream line;
  line << "timeout series " << p.world << " timeout " << report_number(p.leave_timeout)
       << (p.reused ? " (reused)" : "") << ", " << report_number(p.wall_seconds) << " s; "
       << errors_text(p.comparison.errors, "TV distance");
  return line.str();
}

// Summary lines written in their order as soon as each and all before it are known, so the
// output reads the same whatever order the threads finish in.
class LinesInOrder {
 public:
  LinesInOrder(std::ostream& out, std::size_t count) : out_(out), lines_(count) {}
  void set(std::size_t index, std::string line) {
    std::lock_guard lock(mutex_);
    lines_[index] = std::move(line);
    while (next_ < lines_.size() && lines_[next_]) out_ << *lines_[next_++] << std::endl;
  }

 private:
  std::ostream& out_;
  std::vector<std::optional<std::string>> lines_;
  std::size_t next_ = 0;
  std::mutex mutex_;
};

}  // namespace

RatePlots run_rate_plots(const ReproduceOptions& options) {
  return options.run_plots ? RatePlots::Draw : RatePlots::ScriptsOnly;
}

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
  const std::vector<PaperFigure> figures = select_worlds(paper_figures(), options.only);
  const std::vector<TimeoutRun> timeouts =
      timeout_series_selected(options) ? timeout_runs() : std::vector<TimeoutRun>{};
  // An empty report would read as a reproduction in which nothing was checked.
  if (figures.empty() && timeouts.empty()) throw InputError(no_world_selected(options.only));
  // Every experiment compares the paper's controllers with their models: another controller
  // ran, then failed on the model files it has none of.
  const std::vector<WorldOverride> sets = parse_overrides(options.overrides);
  refuse_repeated_keys(sets);
  for (const WorldOverride& o : sets) {
    if (o.key == "controller.type") {
      throw InputError(
          "--set controller.type: reproduce runs the paper's experiments with their own "
          "controllers (Bayindir, Soysal, collision), which its models describe; run another "
          "controller on a paper world with `swarmagg run` or `compare`");
    }
  }
  // Given for a series that will not run, it would be ignored without a word.
  if (options.timeout_duration && timeouts.empty()) {
    throw InputError("--timeout-duration: the leave-timeout series is not selected; add --only " +
                     std::string(kTimeoutFolder) + " (--only picks worlds by name)");
  }
  check_is_a_reproductions_folder(options.out);
  const std::vector<ReproduceJob> jobs = reproduce_jobs(options, figures, timeouts);
  const ThreadSplit split = split_threads(options.threads, jobs.size());
  RunOptions run_options;
  run_options.threads = split.per_job;
  // Progress lines of runs on several threads at once would overwrite each other.
  run_options.progress = options.progress && split.jobs_at_once == 1;

  std::vector<std::optional<FigureResult>> on(figures.size()), off(figures.size());
  std::vector<int> arms_left(figures.size(), 0);
  for (const ReproduceJob& job : jobs) {
    if (!job.timeout) ++arms_left[job.index];
  }
  std::vector<TimeoutPoint> series(timeouts.size());
  std::mutex results;
  LinesInOrder lines(summary, figures.size() + timeouts.size());
  parallel_for(jobs.size(), split.jobs_at_once, [&](std::size_t j) {
    const ReproduceJob& job = jobs[j];
    if (job.timeout) {
      TimeoutPoint point = run_timeout_point(options, *job.timeout, split.per_job);
      const std::string line = timeout_line(point);
      series[job.index] = std::move(point);
      lines.set(figures.size() + job.index, line);
      return;
    }
    const Arm arm = job.compaction_off ? compaction_off_arm(options) : Arm{options.out, {}};
    FigureResult result = reproduce_figure(options, figures[job.index], arm, run_options);
    std::lock_guard lock(results);
    (job.compaction_off ? off : on)[job.index] = std::move(result);
    if (--arms_left[job.index] == 0) {
      lines.set(job.index,
                summary_line(*on[job.index], off[job.index] ? &*off[job.index] : nullptr));
    }
  });
  // A point that is a figure's own run reuses it; run after the figures, so that the two
  // never write one folder at once (without its figure selected, it runs here).
  for (std::size_t t = 0; t < timeouts.size(); ++t) {
    if (!is_paper_run(options, timeouts[t])) continue;
    series[t] = run_timeout_point(options, timeouts[t], split_threads(options.threads, 1).per_job);
    lines.set(figures.size() + t, timeout_line(series[t]));
  }
  ReproduceOutcome outcome;
  for (std::size_t f = 0; f < figures.size(); ++f) {
    outcome.figures.push_back(std::move(*on[f]));
    if (off[f]) outcome.compaction_off.push_back(std::move(*off[f]));
  }
  if (!series.empty()) {
    write_file_atomic(options.out / (std::string(kTimeoutFolder) + ".csv"),
                      timeout_series_csv(series));
    plot_timeout_series(options.out / kPlotFolder, options.plot_size, series);
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
