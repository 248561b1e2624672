#pragma once
// Reads a world file, applies `--set key.path=value` overrides, fills every default and
// checks the result. Any problem is an InputError naming the file, the line, the key and
// what was expected.
#include <string>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

WorldSpec load_world(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from YAML text; `source` names it in messages.
WorldSpec load_world_text(const std::string& text, const std::string& source,
                          const std::vector<std::string>& overrides = {});
// Applies one `key.path=value` override to an already loaded world (then re-checks it).
void apply_override(WorldSpec& spec, const std::string& assignment);
// Cross-key checks (s >= 2r, agents fit, dt > 0, ...); throws InputError.
void check_world(const WorldSpec& spec);

}  // namespace swarmagg
