#pragma once
// Writes a world back as YAML with every key resolved, so `swarmagg validate` shows it and
// a run folder records exactly what ran. The text loads back into an equal WorldSpec.
#include <string>

#include "config/world_spec.hpp"

namespace swarmagg {

std::string world_to_yaml(const WorldSpec& spec);

}  // namespace swarmagg
