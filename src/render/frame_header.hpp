#pragma once
// The text band above the arena, drawn on the CPU into the finished frame: the time, step
// and NOA on the left ("T=12.5  STEP=125  NOA=3"), and on the right, when it fits, a legend
// of the state colours (APPROACH only for Soysal worlds).
#include <cstdint>
#include <span>
#include <string>

#include "observers/swarm_snapshot.hpp"
#include "render/frame_layout.hpp"

namespace swarmagg {

std::string frame_caption(const SwarmSnapshot& snapshot);

// `rgba` is the whole frame, top-down. Returns false when the legend did not fit.
bool draw_frame_header(std::span<std::uint8_t> rgba, const FrameLayout& layout,
                       const SwarmSnapshot& snapshot);

}  // namespace swarmagg
