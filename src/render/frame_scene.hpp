#pragma once
// What a frame draws, in pixels, before any GL: the geometry pass of the renderer, kept
// apart so it can be tested without a context. Layers are drawn in this order:
//   tints   - a disc of radius s/2 under every aggregated agent, in its aggregate's tint;
//             discs of one aggregate merge into one patch, discs of two aggregates do not
//             overlap (their members are more than s apart; not so under join: false,
//             where the links tell the pairs apart);
//   rings   - the detection circle (radius s) of every agent, thin;
//   links   - a line between every two members of one aggregate within s of each other;
//   bodies  - the agent's disc (radius r, at least kMinBodyPixels), filled by state;
//   walls   - the arena border, walls topology only.
// On a torus every shape that crosses the seam is drawn again on the other side(s); the
// renderer clips everything but the walls to the arena.
#include <cstdint>
#include <vector>

#include "geometry/pair_finder.hpp"
#include "observers/swarm_snapshot.hpp"
#include "render/frame_layout.hpp"
#include "render/palette.hpp"

namespace swarmagg {

inline constexpr float kMinBodyPixels = 2.0f;

// A disc of outer radius `radius` whose outermost `line` pixels are drawn in `stroke`
// (line = 0: a plain disc; fill.a = 0: a ring). Centre in top-down pixels.
struct CircleInstance {
  float x = 0.0f;
  float y = 0.0f;
  float radius = 0.0f;
  float line = 0.0f;
  Rgba8 fill;
  Rgba8 stroke;
};

// A segment with round caps, `half_width` pixels either side of its axis.
struct SegmentInstance {
  float x0 = 0.0f;
  float y0 = 0.0f;
  float x1 = 0.0f;
  float y1 = 0.0f;
  float half_width = 0.0f;
  Rgba8 colour;
};

struct FrameScene {
  std::vector<CircleInstance> tints;
  std::vector<CircleInstance> rings;
  std::vector<SegmentInstance> links;
  std::vector<CircleInstance> bodies;
  std::vector<SegmentInstance> walls;
};

// Builds a scene, reusing its buffers from frame to frame (no allocation once warmed up).
class FrameSceneBuilder {
 public:
  const FrameScene& build(const SwarmSnapshot& snapshot, const FrameLayout& layout);

 private:
  void find_links(const SwarmSnapshot& snapshot, const ArenaGeometry& arena);

  // Two members of one aggregate within s: i < j, d from i to j (minimum image).
  struct Link {
    std::int32_t i;
    std::int32_t j;
    Vec2 d;
  };

  FrameScene scene_;
  std::vector<Vec2> wrapped_;                // positions wrapped into the arena (torus)
  std::vector<std::int32_t> lowest_member_;  // per aggregate
  std::vector<std::int32_t> members_;        // aggregated agents
  PairFinder members_finder_;                // over the members, by their index in members_
  std::vector<Link> link_pairs_;
};

}  // namespace swarmagg
