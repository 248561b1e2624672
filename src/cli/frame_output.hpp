#pragma once
// Wires off-screen rendering into a run: which folder frames go to (docs/reference/outputs.md) and
// the observer that records every render.every-th step of replicate render.replicate.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "config/world_override.hpp"
#include "config/world_spec.hpp"
#include "run/replicate_observer.hpp"

namespace swarmagg::cli {

// render.dir when set; else <out>/frames when --out was given; else renders/<world name>.
std::filesystem::path frames_folder(const WorldSpec& spec, const std::filesystem::path& out,
                                    bool out_given);

// The render.width and render.height overrides a "WxH" size stands for (InputError if bad),
// as typed values given by the option `origin`.
std::vector<WorldOverride> render_size_overrides(std::string_view size, const std::string& origin);

// Observers recording frames into `folder` (none when render.every is 0).
ObserverFactory frame_observers(const WorldSpec& spec, const std::filesystem::path& folder);

}  // namespace swarmagg::cli
