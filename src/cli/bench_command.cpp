#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/lib/bare_grid_loop.hpp"
#include "bench/lib/box2d_bench.hpp"
#include "bench/lib/kinematic_bench.hpp"
#include "bench/lib/machine_info.hpp"
#include "bench/lib/render_timing.hpp"
#include "cli/commands.hpp"
#include "cli/paper_worlds.hpp"
#include "config/world_loader.hpp"

namespace swarmagg::cli {
namespace {

struct BenchOptions {
  bool json = false;
  bool quick = false;
  std::string worlds;              // empty: paper_worlds_folder's default
  std::vector<std::string> cases;  // empty: all
};

// The paper's Soysal worlds the bench runs as they are (kinematic_soysal).
const std::vector<std::string> kSoysalWorlds = {"soysal-5-constant", "soysal-10-constant",
                                                "soysal-20-constant"};

bool wanted(const BenchOptions& options, const std::string& name) {
  return options.cases.empty() ||
         std::find(options.cases.begin(), options.cases.end(), name) != options.cases.end();
}

// Agent-steps timed per size and repeat, so every size costs about the same.
double budget_for(bool quick) {
  return quick ? 2e6 : 3e7;
}

// The best of `rounds` timings per size, the rounds going over all sizes in turn rather
// than repeating one size before the next: a virtual machine's speed drifts over minutes,
// and best times taken across the whole run keep the sizes comparable with each other.
using SizeTiming = std::function<KinematicBenchResult(int n, double budget)>;

std::vector<KinematicBenchResult> best_of_rounds(const SizeTiming& time_size, bool quick) {
  const std::vector<int> sizes{1000, 10000, 100000, 1000000};
  std::vector<KinematicBenchResult> best(sizes.size());
  const int rounds = quick ? 1 : 3;
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      const auto r = time_size(sizes[k], budget_for(quick));
      if (r.agent_steps_per_s > best[k].agent_steps_per_s) best[k] = r;
    }
  }
  return best;
}

SizeTiming scenario_timing(BenchScenario scenario) {
  return [scenario](int n, double budget) { return bench_kinematic(n, scenario, budget, 1); };
}

nlohmann::json kinematic_series(const SizeTiming& time_size, bool quick, bool verbose) {
  nlohmann::json series = nlohmann::json::array();
  for (const auto& r : best_of_rounds(time_size, quick)) {
    series.push_back({{"n", r.n},
                      {"warmup_steps", r.warmup_steps},
                      {"steps", r.steps},
                      {"replicates", r.replicates},
                      {"ns_per_agent_step", 1e9 / r.agent_steps_per_s},
                      {"agent_steps_per_s", r.agent_steps_per_s},
                      {"real_time_factor", r.real_time_factor}});
    if (verbose) {
      std::fprintf(stderr, "  n = %7d: %6.2f M agent-steps/s (%5.1f ns each), %8.1f x real time\n",
                   r.n, r.agent_steps_per_s / 1e6, 1e9 / r.agent_steps_per_s, r.real_time_factor);
    }
  }
  return series;
}

nlohmann::json box2d_series(bool quick, bool verbose) {
  nlohmann::json series = nlohmann::json::array();
  for (int n : {100, 1000, 10000}) {
    // Five interleaved rounds: with three, the VM's drift still moved the ratio by ±0.15.
    const auto r = bench_box2d(n, static_cast<int>(budget_for(quick) / 10 / n), quick ? 1 : 5);
    series.push_back({{"n", r.n},
                      {"body_steps_per_s", r.body_steps_per_s},
                      {"bare_box2d_body_steps_per_s", r.bare_box2d_body_steps_per_s},
                      {"real_time_factor", r.body_steps_per_s / n * 0.1}});
    if (verbose) {
      std::fprintf(stderr, "  n = %5d: %6.3f M body-steps/s (bare Box2D %6.3f M, ratio %.2f)\n", n,
                   r.body_steps_per_s / 1e6, r.bare_box2d_body_steps_per_s / 1e6, r.overhead());
    }
  }
  return series;
}

// Each world is loaded before any is timed, so that a missing one fails at once.
nlohmann::json soysal_series(const BenchOptions& options, bool verbose) {
  std::vector<WorldSpec> worlds;
  const std::string folder = paper_worlds_folder(options.worlds);
  for (const std::string& name : kSoysalWorlds) {
    worlds.push_back(load_world(folder + "/" + name + ".yaml"));
  }
  nlohmann::json series = nlohmann::json::array();
  for (std::size_t k = 0; k < worlds.size(); ++k) {
    const auto r = bench_world_run(worlds[k], budget_for(options.quick));
    series.push_back({{"world", kSoysalWorlds[k]},
                      {"n", r.n},
                      {"steps", r.steps},
                      {"steps_per_s", r.agent_steps_per_s / r.n},
                      {"ns_per_agent_step", 1e9 / r.agent_steps_per_s},
                      {"agent_steps_per_s", r.agent_steps_per_s},
                      {"real_time_factor", r.real_time_factor}});
    if (verbose) {
      std::fprintf(stderr, "  %-19s %8lld steps: %6.2f M agent-steps/s (%5.1f ns each)\n",
                   kSoysalWorlds[k].c_str(), static_cast<long long>(r.steps),
                   r.agent_steps_per_s / 1e6, 1e9 / r.agent_steps_per_s);
    }
  }
  return series;
}

const nlohmann::json* entry_for(const nlohmann::json& series, int n) {
  for (const auto& entry : series) {
    if (entry["n"].get<int>() == n) return &entry;
  }
  return nullptr;
}

// What the kinematic series say together: the full model's speed over the bare loop's at
// each N (both in this run), and each series' cost per agent-step at 10^6 agents over its cost
// at 10^3 (how well it scales).
nlohmann::json kinematic_ratios(const nlohmann::json& report, bool verbose) {
  nlohmann::json ratios = nlohmann::json::object();
  if (report.contains("kinematic_bayindir") && report.contains("kinematic_bare")) {
    nlohmann::json over_bare = nlohmann::json::array();
    for (const auto& full : report["kinematic_bayindir"]) {
      const int n = full["n"].get<int>();
      const nlohmann::json* bare = entry_for(report["kinematic_bare"], n);
      if (bare == nullptr) continue;
      const double ratio =
          full["agent_steps_per_s"].get<double>() / (*bare)["agent_steps_per_s"].get<double>();
      over_bare.push_back({{"n", n}, {"ratio", ratio}});
      if (verbose) std::fprintf(stderr, "  Bayindir / bare loop at n = %7d: %.2f\n", n, ratio);
    }
    ratios["bayindir_over_bare"] = over_bare;
  }
  for (const char* name : {"kinematic", "kinematic_bayindir", "kinematic_bare"}) {
    if (!report.contains(name)) continue;
    const nlohmann::json* small = entry_for(report[name], 1000);
    const nlohmann::json* large = entry_for(report[name], 1000000);
    if (small == nullptr || large == nullptr) continue;
    const double ratio =
        (*large)["ns_per_agent_step"].get<double>() / (*small)["ns_per_agent_step"].get<double>();
    ratios[std::string(name) + "_cost_1e6_over_1e3"] = ratio;
    if (verbose)
      std::fprintf(stderr, "  %s: cost per agent-step at 10^6 / 10^3 = %.2f\n", name, ratio);
  }
  return ratios;
}

int bench_command(const BenchOptions& options) {
  const bool verbose = !options.json;
  nlohmann::json report;
  if (wanted(options, "soysal")) {
    if (verbose)
      std::fprintf(stderr, "kinematic, the paper's Soysal worlds from t = 0, one thread:\n");
    report["kinematic_soysal"] = soysal_series(options, verbose);
  }
  if (wanted(options, "ghost")) {
    if (verbose) std::fprintf(stderr, "kinematic, worst case (ghost collisions), one thread:\n");
    report["kinematic"] =
        kinematic_series(scenario_timing(BenchScenario::GhostWorstCase), options.quick, verbose);
  }
  if (wanted(options, "bayindir")) {
    if (verbose) std::fprintf(stderr, "kinematic, Bayindir full model p = 0.001, one thread:\n");
    report["kinematic_bayindir"] =
        kinematic_series(scenario_timing(BenchScenario::BayindirFull), options.quick, verbose);
  }
  if (wanted(options, "bare")) {
    if (verbose)
      std::fprintf(stderr, "bare loop (move, wrap, grid, pairs within s), one thread:\n");
    report["kinematic_bare"] = kinematic_series(bench_bare_grid_loop, options.quick, verbose);
  }
  if (const nlohmann::json ratios = kinematic_ratios(report, verbose); !ratios.empty()) {
    report["kinematic_ratios"] = ratios;
  }
  if (wanted(options, "box2d")) {
    if (verbose) std::fprintf(stderr, "box2d engine vs bare Box2D:\n");
    report["box2d"] = box2d_series(options.quick, verbose);
  }
  if (wanted(options, "render")) {
    report["render_ms_per_frame"] = render_ms_per_frame(1000, 800, 800, options.quick ? 5 : 30);
    if (verbose) {
      std::fprintf(stderr, "render: %.1f ms per 800x800 frame with 1000 agents (drawing only)\n",
                   report["render_ms_per_frame"].get<double>());
    }
  }
  report["machine"] = machine_info();
  if (options.json) std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace

void add_bench_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* command = app.add_subcommand(
      "bench", "Measure throughput: kinematic and Box2D engines, rendering (docs/performance.md)");
  command->add_flag("--json", options->json, "Print one JSON object (for scripts)");
  command->add_flag("--quick", options->quick, "Fewer steps per size (same sizes)");
  command->add_option("--worlds", options->worlds,
                      "Folder of the paper worlds (" + paper_worlds_default_help() + ")");
  command
      ->add_option("--case", options->cases,
                   "Only these cases (repeatable): soysal, ghost, bayindir, bare, box2d, render")
      ->check(CLI::IsMember({"soysal", "ghost", "bayindir", "bare", "box2d", "render"}));
  command->callback([options, &action] { action = [options] { return bench_command(*options); }; });
}

}  // namespace swarmagg::cli
