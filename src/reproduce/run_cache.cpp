#include "reproduce/run_cache.hpp"

#include <fstream>
#include <sstream>

#include "config/world_writer.hpp"
#include "reproduce/paper_predictions.hpp"
#include "run/model_outputs.hpp"
#include "run/run_folder.hpp"

namespace swarmagg {
namespace {

std::string without_comment_lines(std::istream& in) {
  std::string body, line;
  while (std::getline(in, line)) {
    if (!line.starts_with("#")) body += line + "\n";
  }
  return body;
}

}  // namespace

bool run_is_reusable(const WorldSpec& spec, const std::filesystem::path& folder) {
  std::ifstream resolved(folder / "world.resolved.yaml");
  if (!resolved || !std::filesystem::exists(folder / "timeseries.csv") ||
      !std::filesystem::exists(folder / "model.csv")) {
    return false;
  }
  std::istringstream current(world_to_yaml(spec));
  return without_comment_lines(resolved) == without_comment_lines(current);
}

bool ensure_run(const WorldSpec& spec, const std::filesystem::path& folder,
                const RunOptions& options) {
  if (run_is_reusable(spec, folder)) return true;
  // The models first: world.resolved.yaml, written last by write_run_folder, then marks
  // the folder complete with its model outputs beside it.
  std::filesystem::remove(folder / "world.resolved.yaml");
  write_model_outputs(spec, paper_predictions(spec), folder);
  write_run_folder(spec, run_world(spec, options), folder);
  return false;
}

}  // namespace swarmagg
