#include "reproduce/timeout_series.hpp"

#include <chrono>
#include <cmath>

#include "analysis/csv_table.hpp"
#include "analysis/csv_text.hpp"
#include "analysis/run_files.hpp"
#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "plot/variant_colours.hpp"
#include "rates/rates_csv.hpp"
#include "reproduce/run_cache.hpp"

namespace swarmagg {

namespace {

using Clock = std::chrono::steady_clock;

std::string run_name(const std::string& world, double timeout) {
  return world + "-timeout-" + csv_number(timeout);
}

}  // namespace

bool timeout_series_selected(const ReproduceOptions& options) {
  if (options.only.empty()) return true;
  for (const std::string& pattern : options.only) {
    if (std::string(kTimeoutFolder).find(pattern) != std::string::npos) return true;
  }
  return false;
}

// The series' run length is --timeout-duration's, divided like every run length under --quick.
WorldSpec timeout_world(const ReproduceOptions& options, const TimeoutRun& run) {
  WorldSpec world = load_world((options.worlds / (run.world + ".yaml")).string());
  for (const WorldOverride& o : reproduce_overrides(options, world)) apply_override(world, o);
  if (options.timeout_duration) {
    const double divisor = options.quick ? kQuickDurationDivisor : 1.0;
    apply_override(world, typed_override("run.duration", *options.timeout_duration / divisor,
                                         "--timeout-duration"));
  }
  apply_override(world, typed_override("controller.leave_timeout", run.leave_timeout,
                                       "reproduce (timeout series)"));
  world.name = run_name(run.world, run.leave_timeout);
  check_world(world);
  return world;
}

namespace {

WorldSpec paper_world(const ReproduceOptions& options, const std::string& name) {
  WorldSpec world = load_world((options.worlds / (name + ".yaml")).string());
  for (const WorldOverride& o : reproduce_overrides(options, world)) apply_override(world, o);
  check_world(world);
  return world;
}

}  // namespace

bool is_paper_run(const ReproduceOptions& options, const TimeoutRun& run) {
  WorldSpec point = timeout_world(options, run);
  const WorldSpec paper = paper_world(options, run.world);
  point.name = paper.name;
  return world_to_yaml(point) == world_to_yaml(paper);
}

std::vector<TimeoutRun> timeout_runs() {
  std::vector<TimeoutRun> runs;
  for (const char* world : kTimeoutWorlds) {
    for (const double timeout : kLeaveTimeouts) runs.push_back({world, timeout});
  }
  return runs;
}

TimeoutPoint run_timeout_point(const ReproduceOptions& options, const TimeoutRun& run,
                               int run_threads) {
  const auto start = Clock::now();
  const bool paper = is_paper_run(options, run);
  const WorldSpec world = paper ? paper_world(options, run.world) : timeout_world(options, run);
  const std::filesystem::path folder = paper ? options.out / "runs" / world.name
                                             : options.out / kTimeoutFolder / "runs" / world.name;
  RunOptions run_options;
  run_options.threads = run_threads;
  run_options.progress = options.progress;
  TimeoutPoint point{.world = run.world,
                     .agents = world.robots.count,
                     .leave_timeout = run.leave_timeout,
                     .duration = world.run.duration,
                     .replicates = world.run.replicates,
                     .paper_run = paper};
  point.reused = ensure_run(world, folder, run_options, run_rate_plots(options));
  point.comparison = compare_partitions(folder);
  point.rates = read_rates_csv(folder / "rates.csv");
  point.trend = second_half_trend(read_step_series(folder / "timeseries.csv", "noa"));
  point.simulation_seconds = read_run_files(folder).wall_seconds;
  point.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return point;
}

std::string timeout_series_csv(const std::vector<TimeoutPoint>& points) {
  std::string text =
      "world,agents,leave_timeout,duration,replicates,variant,tv_partition,noise_floor,"
      "noa_trend,noa_trend_low,noa_trend_high\n";
  for (const TimeoutPoint& p : points) {
    for (const VariantError& e : p.comparison.errors) {
      text += p.world + "," + std::to_string(p.agents) + "," + csv_number(p.leave_timeout) + "," +
              csv_number(p.duration) + "," + std::to_string(p.replicates) + "," + e.variant + "," +
              csv_number(e.error) + "," + (e.noise_floor ? csv_number(*e.noise_floor) : "") + "," +
              csv_number(p.trend.change) + "," + csv_number(p.trend.low) + "," +
              csv_number(p.trend.high) + "\n";
    }
  }
  return text;
}

// One table per world, a row per timeout: each variant's TV distance and noise floor.
std::string world_table(const std::vector<TimeoutPoint>& points, const std::string& world,
                        const std::vector<std::string>& variants) {
  std::string text = "leave_timeout";
  for (const std::string& v : variants) text += "," + v + "," + v + "_floor";
  text += "\n";
  for (const TimeoutPoint& p : points) {
    if (p.world != world) continue;
    text += csv_number(p.leave_timeout);
    for (const std::string& v : variants) {
      const VariantError* found = nullptr;
      for (const VariantError& e : p.comparison.errors) {
        if (e.variant == v) found = &e;
      }
      text += "," + (found ? csv_number(found->error) : "") + "," +
              (found && found->noise_floor ? csv_number(*found->noise_floor) : "");
    }
    text += "\n";
  }
  return text;
}

// One panel per world: each variant's TV distance (solid) and noise floor (dashed) against
// the leave timeout.
void plot_timeout_series(const std::filesystem::path& plots, const PlotSize& size,
                         const std::vector<TimeoutPoint>& points) {
  if (points.empty()) return;
  std::filesystem::create_directories(plots);
  std::vector<std::string> variants;
  for (const VariantError& e : points.front().comparison.errors) variants.push_back(e.variant);
  std::string script = png_preamble(size, "timeout-series.png",
                                    "Soysal partitions: error against the leave timeout");
  script +=
      "set datafile separator ','\nset multiplot layout 1,2\nset xlabel 'leave timeout (tu)'\n"
      "set ylabel 'TV distance (dashed: noise floor)'\nset yrange [0:1]\nset key top right\n";
  for (const char* world : kTimeoutWorlds) {
    const std::string csv = std::string("timeout-series-") + world + ".csv";
    write_file_atomic(plots / csv, world_table(points, world, variants));
    script += "set title " + gnuplot_quote(world) + " noenhanced\nplot ";
    for (std::size_t k = 0; k < variants.size(); ++k) {
      const std::string colour = " lc rgb " + gnuplot_quote(variant_colour(k));
      const std::string column = std::to_string(2 + 2 * k);
      script += std::string(k == 0 ? "" : ", \\\n  ") + gnuplot_quote(csv) +
                " skip 1 using 1:" + column + " with linespoints lw 2 pt 7" + colour + " title " +
                gnuplot_quote(variants[k]) + ", \\\n  " + gnuplot_quote(csv) +
                " skip 1 using 1:" + std::to_string(3 + 2 * k) + " with lines dt 2" + colour +
                " notitle";
    }
    script += "\n";
  }
  script += "unset multiplot\n";
  run_gnuplot(plots / "timeout-series.gp", script);
}

}  // namespace swarmagg
