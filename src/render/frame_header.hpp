#pragma once
// The text band above the arena, part of the scene (frame_scene.hpp) and drawn on the CPU
// into the finished frame: the time, step and NOA on the left ("T=12.5  STEP=125  NOA=3"),
// and on the right, when it fits, a legend of the state colours (APPROACH only for Soysal
// worlds).
#include <cstdint>
#include <span>
#include <string>

#include "observers/swarm_snapshot.hpp"
#include "render/frame_layout.hpp"

namespace swarmagg {

std::string frame_caption(const SwarmSnapshot& snapshot);

struct FrameScene;

// Appends the header's labels and legend swatches to `scene`. Returns false when the legend
// did not fit.
bool add_frame_header(FrameScene& scene, const FrameLayout& layout, const SwarmSnapshot& snapshot);

// The header alone, into `rgba` (the whole frame, top-down); as add_frame_header.
bool draw_frame_header(std::span<std::uint8_t> rgba, const FrameLayout& layout,
                       const SwarmSnapshot& snapshot);

}  // namespace swarmagg
