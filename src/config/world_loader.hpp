#pragma once
// Reads a world file, applies `--set key.path=value` overrides, fills every default and
// checks the result. Any problem is an InputError naming the file, the line, the key and
// what was expected.
#include <string>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

struct WorldOverride;  // config/world_override.hpp, for the callers that make them

WorldSpec load_world_with(const std::string& path, const std::vector<WorldOverride>& overrides);
// The same with `--set` assignments (`key.path=value`, the value read as YAML).
WorldSpec load_world(const std::string& path, const std::vector<std::string>& assignments = {});
// The same from YAML text; `source` names it in messages.
WorldSpec load_world_text_with(const std::string& text, const std::string& source,
                               const std::vector<WorldOverride>& overrides);
WorldSpec load_world_text(const std::string& text, const std::string& source,
                          const std::vector<std::string>& assignments = {});
// Applies one override to an already loaded world; the caller re-checks it (check_world).
void apply_override(WorldSpec& spec, const WorldOverride& override);
// Cross-key checks (s >= 2r, agents fit, dt > 0, ...); throws InputError.
void check_world(const WorldSpec& spec);
// Refuses (InputError) an override of a controller.* key that the world's controller type does
// not read, or of a model.* key its model does not read: the run would ignore it, while
// summary.json and the plots list it as a change (a sweep would plot a parameter that changed
// nothing). A world file may hold model keys its model ignores: the resolved world writes every
// model key, so that `--set controller.type` on it, or a sweep over controller types, gives
// each model what the file said. Overrides marked any_controller pass (a sweep over controller
// types gives a key one type reads to every point; a sweep's recorded points were checked when
// it began), and `reproduce`, which applies one override to worlds of several controllers,
// does not call this.
void check_overrides_read(const WorldSpec& spec, const std::vector<WorldOverride>& overrides);
// Whether controller type `type` reads `path` (false for a controller.* key it ignores or a
// model.* key its model ignores; true for any other key).
bool controller_type_reads(const std::string& type, const std::string& path);

}  // namespace swarmagg
