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
  refuse_repeated_keys(all);
  std::vector<WorldOverride> from_options;
  if (engine) from_options.push_back(typed_override("engine.type", *engine, "--engine"));
  if (replicates)
    from_options.push_back(typed_override("run.replicates", *replicates, "--replicates"));
  if (seed) from_options.push_back(typed_override("run.seed", *seed, "--seed"));
  if (threads) from_options.push_back(typed_override("run.threads", *threads, "--threads"));
  from_options.insert(from_options.end(), typed_overrides.begin(), typed_overrides.end());
  // An option and a --set of its key would leave one of the two silently unused.
  for (const WorldOverride& option : from_options) {
    for (const WorldOverride& set : all) {
      if (set.key == option.key)
        throw InputError(option.origin + " and --set " + set.key + " both set " + set.key +
                         ": give one of them");
    }
  }
  all.insert(all.end(), from_options.begin(), from_options.end());
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
