#pragma once
// The options every world-taking subcommand shares: the world file, --set overrides and
// the common shortcuts, each of which is just another override of a world key.
#include <optional>
#include <string>
#include <vector>

#include "config/world_override.hpp"
#include "config/world_spec.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace swarmagg::cli {

struct WorldOptions {
  std::string path;
  std::vector<std::string> overrides;          // --set key.path=value
  std::vector<WorldOverride> typed_overrides;  // from typed options, applied after --set
  std::optional<std::string> engine;
  std::optional<int> replicates;
  // As typed: run.seed's own reader checks it (CLI11 would wrap -1 and clamp 2^64 silently).
  std::optional<std::string> seed;
  std::optional<int> threads;

  // Adds WORLD and --set; with `run_options`, also --engine/--replicates/--seed/--threads.
  void add_to(CLI::App& command, bool run_options = true);
  WorldSpec load() const;
  // What these options change of the world file's simulation, as key=value
  // ("robots.count=80", "engine.type=box2d"), in the order given; not run.threads, which
  // changes no result.
  std::vector<std::string> changes() const;
};

}  // namespace swarmagg::cli
