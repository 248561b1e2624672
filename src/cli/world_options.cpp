#include "cli/world_options.hpp"

#include <CLI/CLI.hpp>

#include "config/world_loader.hpp"
#include "core/errors.hpp"

namespace swarmagg::cli {

void WorldOptions::add_to(CLI::App& command, bool run_options) {
  command.add_option("world", path, "World file (YAML)")->required();
  command.add_option("--set", overrides,
                     "Override a world key, e.g. --set robots.count=80 (repeatable)");
  if (!run_options) return;
  command.add_option("--engine", engine, "Engine: kinematic or box2d (engine.type)");
  command.add_option("--replicates", replicates, "Number of replicates (run.replicates)");
  command.add_option("--seed", seed, "World seed (run.seed)")->type_name("UINT");
  command.add_option("--threads", threads, "Threads (run.threads; 0 = all cores)");
}

WorldSpec WorldOptions::load() const {
  std::vector<WorldOverride> all = parse_overrides(overrides);
  // An option and a --set of its key would leave one of the two silently unused.
  const auto add_option = [&all](const std::string& key, const auto& value,
                                 const std::string& option) {
    for (const WorldOverride& set : all) {
      if (set.key == key)
        throw InputError(option + " and --set " + key + " both set " + key + ": give one of them");
    }
    all.push_back(typed_override(key, value, option));
  };
  if (engine) add_option("engine.type", *engine, "--engine");
  if (replicates) add_option("run.replicates", *replicates, "--replicates");
  if (seed) add_option("run.seed", *seed, "--seed");
  if (threads) add_option("run.threads", *threads, "--threads");
  all.insert(all.end(), typed_overrides.begin(), typed_overrides.end());
  return load_world_with(path, all);
}

std::vector<std::string> WorldOptions::changes() const {
  std::vector<std::string> result = overrides;
  if (engine) result.push_back("engine.type=" + *engine);
  if (replicates) result.push_back("run.replicates=" + std::to_string(*replicates));
  if (seed) result.push_back("run.seed=" + *seed);
  return result;
}

}  // namespace swarmagg::cli
