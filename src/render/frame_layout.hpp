#pragma once
// Where things go in a frame: a header band at the top holds the text (time, step, NOA,
// legend); the arena is scaled uniformly to fit the rest, centred, arena y pointing up.
// Pixel coordinates run top-down: pixel (col, row) covers [col, col+1) x [row, row+1),
// so its centre is (col + 0.5, row + 0.5).
#include "config/world_spec.hpp"
#include "core/vec2.hpp"

namespace swarmagg {

struct PixelRect {
  int left = 0;
  int top = 0;
  int width = 0;
  int height = 0;
};

struct FrameLayout {
  int width = 0;  // image, pixels
  int height = 0;
  int text_scale = 1;     // bitmap font magnification (5x7 glyphs -> 5k x 7k pixels)
  int header_height = 0;  // pixels above the arena reserved for text
  double scale = 1.0;     // pixels per arena unit
  double arena_width = 0.0;
  double arena_height = 0.0;
  double origin_x = 0.0;  // pixel position of the arena point (0, arena_height)
  double origin_y = 0.0;
  PixelRect arena;  // the arena's pixels, rounded outwards to whole pixels

  // Top-down pixel coordinates of an arena point.
  Vec2 to_pixel(Vec2 p) const {
    return {origin_x + p.x * scale, origin_y + (arena_height - p.y) * scale};
  }
  // The arena point under a top-down pixel position (the inverse of to_pixel).
  Vec2 to_arena(Vec2 pixel) const {
    return {(pixel.x - origin_x) / scale, arena_height - (pixel.y - origin_y) / scale};
  }
  // The part of the image below the header band, where the arena is drawn.
  PixelRect view() const { return {0, header_height, width, height - header_height}; }
};

// Throws InputError for sizes outside render_size.hpp's bounds or an empty arena.
FrameLayout make_frame_layout(int width, int height, const ArenaSpec& arena);

// `fit` magnified `zoom` times about the arena point `centre`, which lands at the centre of
// the view below the header; `arena` is clipped to that view. zoom 1 about the arena's
// centre is `fit` itself.
FrameLayout zoomed_layout(const FrameLayout& fit, double zoom, Vec2 centre);

}  // namespace swarmagg
