#include "sweep/sweep_status.hpp"

#include <fstream>
#include <sstream>

#include "config/world_writer.hpp"

namespace swarmagg {

RunStatus sweep_run_status(const std::filesystem::path& out, const SweepRun& run) {
  const std::filesystem::path folder = sweep_run_folder(out, run);
  // The file name write_run_folder gives the resolved world (run/run_folder.hpp).
  std::ifstream in(folder / "world.resolved.yaml", std::ios::binary);
  if (!in) return std::filesystem::exists(folder) ? RunStatus::Unfinished : RunStatus::Pending;
  std::ostringstream text;
  text << in.rdbuf();
  // The file is comment lines (version, seeds) followed by world_to_yaml of the run's world.
  return text.str().ends_with(world_to_yaml(run.world)) ? RunStatus::Complete : RunStatus::Outdated;
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
