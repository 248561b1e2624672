#pragma once
// What a frame draws, in pixels, before any GL: the one scene both the off-screen renderer
// (PNG frames) and the live view's window draw, a pure function of a snapshot, a layout
// and the view's options (scene_options.hpp), kept apart so it can be tested without a
// context. With the default options, layers are drawn in this order:
//   tints   - a disc of radius s/2 under every aggregated agent, in its aggregate's tint;
//             discs of one aggregate merge into one patch, discs of two aggregates do not
//             overlap (their members are more than s apart; not so under join: false,
//             where the links tell the pairs apart);
//   rings   - the detection circle (radius s) of every agent, thin;
//   links   - a line between every two members of one aggregate within s of each other;
//   bodies  - the agent's disc (radius r, at least kMinBodyPixels), filled by state;
//   marks   - a ring around the selected agent (none by default);
//   walls   - the arena border, walls topology only;
//   rects, labels - the header band's caption and legend (frame_header.hpp) and the selected
//             agent's id, in the built-in bitmap font, drawn last on the CPU, unclipped.
// On a torus every shape that crosses the seam is drawn again on the other side(s) (unless
// options.ghosts is off); the renderer clips everything but the walls to the arena.
// Options may colour bodies by aggregate or aggregate size, draw the detection and approach
// circles for the selected agent only or for all, and add to the links layer, below the
// aggregate links, trails and every neighbour pair, and above them the touching pairs.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geometry/pair_finder.hpp"
#include "observers/swarm_snapshot.hpp"
#include "render/frame_layout.hpp"
#include "render/palette.hpp"
#include "render/scene_options.hpp"

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

// A line of text in the built-in 5x7 font (bitmap_font.hpp), top-left corner at (x, y),
// glyphs magnified `scale` times; and a filled rectangle. Whole pixels, top-down.
struct TextLabel {
  int x = 0;
  int y = 0;
  int scale = 1;
  Rgba8 colour;
  std::string text;
};

struct FilledRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  Rgba8 colour;
};

struct FrameScene {
  std::vector<CircleInstance> tints;
  std::vector<CircleInstance> rings;
  std::vector<SegmentInstance> links;
  std::vector<CircleInstance> bodies;
  std::vector<CircleInstance> marks;
  std::vector<SegmentInstance> walls;
  std::vector<FilledRect> rects;
  std::vector<TextLabel> labels;
};

// Draws the scene's rects, then its labels, into the finished frame (`rgba`, top-down,
// width x height).
void draw_scene_text(std::span<std::uint8_t> rgba, int width, int height, const FrameScene& scene);

// Builds a scene, reusing its buffers from frame to frame (no allocation once warmed up).
class FrameSceneBuilder {
 public:
  // `layout` is the frame's fit layout; options.zoom and options.centre apply to it
  // (layout_for below).
  const FrameScene& build(const SwarmSnapshot& snapshot, const FrameLayout& layout,
                          const SceneOptions& options = {}, const SceneExtras& extras = {});

  // The layout the shapes are placed with: `fit` zoomed as the options say.
  static FrameLayout layout_for(const FrameLayout& fit, const SceneOptions& options);

 private:
  void find_links(const SwarmSnapshot& snapshot, const ArenaGeometry& arena);
  void add_pair_segments(const SwarmSnapshot& snapshot, const FrameLayout& layout,
                         const SceneOptions& options, double extent, float half_width);
  void add_selection_label(const FrameLayout& layout, const SceneOptions& options);
  void add_trails(const SwarmSnapshot& snapshot, const FrameLayout& layout,
                  const SceneExtras& extras, float half_width);
  Rgba8 body_colour(const SwarmSnapshot& snapshot, std::int32_t agent) const;

  // Two members of one aggregate within s: i < j, d from i to j (minimum image).
  struct Link {
    std::int32_t i;
    std::int32_t j;
    Vec2 d;
  };

  FrameScene scene_;
  std::vector<Vec2> wrapped_;                 // positions wrapped into the arena (torus)
  std::vector<std::int32_t> lowest_member_;   // per aggregate
  std::vector<std::int32_t> aggregate_size_;  // per aggregate
  ColourMode colour_ = ColourMode::State;
  std::vector<std::int32_t> members_;  // aggregated agents
  PairFinder members_finder_;          // over the members, by their index in members_
  std::vector<Link> link_pairs_;
  PairFinder all_finder_;  // over every agent, for neighbour links and contacts
  std::vector<Link> near_pairs_;
};

// The agent drawn under the top-down pixel position `pixel` (any of its seam copies), within
// `tolerance` pixels of its body; the nearest one if several; -1 if none.
std::int32_t pick_agent(const SwarmSnapshot& snapshot, const FrameLayout& layout, Vec2 pixel,
                        float tolerance = 3.0f);

}  // namespace swarmagg
