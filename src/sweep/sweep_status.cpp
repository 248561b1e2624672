#include "sweep/sweep_status.hpp"

#include <fstream>
#include <sstream>

#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "core/errors.hpp"

namespace swarmagg {

namespace {

// A run's world without the keys its outputs do not depend on: its threads (results are the
// same at any count) and render.* (a sweep draws no frames). A base world given one of them
// later keeps the sweep's runs.
std::string outcome_relevant(WorldSpec world) {
  world.run.threads = WorldSpec{}.run.threads;
  world.render = WorldSpec{}.render;
  return world_to_yaml(world);
}

bool same_outcome(const std::string& stored, const WorldSpec& world) {
  try {
    return outcome_relevant(load_world_text(stored, "world.resolved.yaml")) ==
           outcome_relevant(world);
  } catch (const InputError&) {
    return false;  // a world this version cannot read: run it again
  }
}

}  // namespace

RunStatus sweep_run_status(const std::filesystem::path& out, const SweepRun& run) {
  const std::filesystem::path folder = sweep_run_folder(out, run);
  // The file name write_run_folder gives the resolved world (run/run_folder.hpp).
  std::ifstream in(folder / "world.resolved.yaml", std::ios::binary);
  if (!in) return std::filesystem::exists(folder) ? RunStatus::Unfinished : RunStatus::Pending;
  std::ostringstream text;
  text << in.rdbuf();
  // The file is comment lines (version, seeds) followed by world_to_yaml of the run's world.
  if (text.str().ends_with(world_to_yaml(run.world))) return RunStatus::Complete;
  return same_outcome(text.str(), run.world) ? RunStatus::Complete : RunStatus::Outdated;
}

const char* status_name(RunStatus status) {
  switch (status) {
    case RunStatus::Pending:
      return "pending";
    case RunStatus::Unfinished:
      return "unfinished";
    case RunStatus::Outdated:
      return "outdated";
    case RunStatus::Complete:
      return "complete";
  }
  return "pending";
}

}  // namespace swarmagg
