#include "compare/engine_comparison.hpp"

#include <stdexcept>

#include "compare/compare_plots.hpp"
#include "compare/compare_summary.hpp"
#include "config/world_loader.hpp"
#include "config/world_override.hpp"
#include "engine/engine.hpp"
#include "output/atomic_file.hpp"
#include "run/earlier_run.hpp"
#include "run/run_folder.hpp"

namespace swarmagg {
WorldSpec on_engine(const WorldSpec& spec, const std::string& engine) {
  WorldSpec copy = spec;
  apply_override(copy, typed_override("engine.type", engine, "compare"));
  check_world(copy);
  check_engine_world(copy);  // the Box2D arm's limits, before the kinematic arm runs
  return copy;
}

EngineComparison compare_engines(const WorldSpec& spec, bool progress,
                                 const std::filesystem::path& out) {
  // Both arms' worlds first: one the other engine cannot run is refused before any run.
  const WorldSpec on_kinematic = on_engine(spec, "kinematic");
  const WorldSpec on_box2d = on_engine(spec, "box2d");
  EngineComparison result;
  result.kinematic = run_arm("kinematic", on_kinematic, progress, out);
  result.box2d = run_arm("box2d", on_box2d, progress, out);
  result.stats = compare_arms(result.kinematic, result.box2d);
  return result;
}

std::vector<std::string> write_compare_folder(const ArmResult& a, const ArmResult& b,
                                              const Comparison& c, const std::filesystem::path& out,
                                              const std::vector<std::string>& changes) {
  const std::string& world = a.spec.name;
  for (const ArmResult* arm : {&a, &b}) {
    // Spooled rows land where compare_engines was told; noa.csv reads them back from `out`.
    if (arm->timeseries && arm->timeseries->target() != out / arm->label / "timeseries.csv")
      throw std::invalid_argument("write_compare_folder: the arms' rows were spooled for " +
                                  arm->timeseries->target().string());
  }
  std::filesystem::create_directories(out);
  for (const ArmResult* arm : {&a, &b}) {
    std::vector<std::string> arm_changes = changes;
    arm_changes.push_back("engine.type=" + arm->label);
    write_run_folder(arm->spec, arm->run, out / arm->label, arm_changes, arm->timeseries.get());
  }
  write_file_atomic(out / "compare.json", comparison_json(world, c).dump(2) + "\n");
  write_file_atomic(out / "summary.txt", comparison_text(world, c));
  // Absolute: run_gnuplot fails to start gnuplot for a relative script path (seen with
  // --out runs/x; reported to the plot owner).
  return write_comparison_plots(world, a, b, c, std::filesystem::absolute(out));
}

std::vector<std::string> remove_earlier_comparison(const std::filesystem::path& out) {
  std::vector<std::string> failures;
  for (const char* name : {"kinematic", "box2d", "summary.txt", "compare.json", "noa.csv", "noa.gp",
                           "noa.png", "final_noa.csv", "sizes.csv", "final.gp", "final.png",
                           "escape_rate.csv", "escape_rate.gp", "escape_rate.png"}) {
    remove_earlier_output(out / name, failures);
  }
  return failures;
}

std::filesystem::path default_compare_folder(const WorldSpec& spec) {
  return std::filesystem::path("runs") / (spec.name + "-compare");
}

}  // namespace swarmagg
