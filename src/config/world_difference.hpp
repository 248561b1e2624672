#pragma once
// Whether two worlds are the same system: the same arena, robots, controller and engine, the
// keys a run's results depend on apart from its length, replicates, seed and outputs. Used
// where a command meets outputs of another world (a run folder it writes into, rates it
// reads) and must not mix the two silently.
#include <string>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

// The keys whose values differ, as "key: <there> there, <here> here", in the order of the
// resolved world text; empty when the two are the same system. `there` is a resolved world
// text (world.resolved.yaml, or world_to_yaml), read as a world where it can be (so keys an
// older version did not write take their defaults); one that cannot be read, or holds none of
// the sections, differs as "the world text: unreadable". Box2D settings do not tell two
// kinematic worlds apart.
std::vector<std::string> system_differences(const std::string& there, const WorldSpec& here);
// The system's differences and those of the run keys a model's errors against a run depend on
// (the steps run.duration / engine.dt, run.record_every, run.replicates: the noise floors are
// batches of replicates).
std::vector<std::string> measured_run_differences(const std::string& there, const WorldSpec& here);

// Every key whose value differs between two worlds, as "key=value" with `changed`'s value, in
// the order of the resolved world text; not `name` (a renamed copy runs the same experiment).
// What a command changed in a world file's world, for summary.json's overrides.
std::vector<std::string> changed_keys(const WorldSpec& original, const WorldSpec& changed);

// The first few differences joined for a message ("robots.count: 60 there, 10 here; ...").
std::string differences_text(const std::vector<std::string>& differences);

}  // namespace swarmagg
