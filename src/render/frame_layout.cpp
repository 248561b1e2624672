#include "render/frame_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "render/bitmap_font.hpp"
#include "render/render_size.hpp"

namespace swarmagg {

FrameLayout make_frame_layout(int width, int height, const ArenaSpec& arena) {
  validate_render_size(width, height);
  if (!(arena.width > 0.0) || !(arena.height > 0.0) || !std::isfinite(arena.width) ||
      !std::isfinite(arena.height)) {
    throw InputError("cannot render an arena of " + std::to_string(arena.width) + " x " +
                     std::to_string(arena.height));
  }
  FrameLayout layout;
  layout.width = width;
  layout.height = height;
  layout.text_scale = std::max(1, std::min(width, height) / 400);
  layout.header_height = (kGlyphHeight + 2 * kTextPadding) * layout.text_scale;
  layout.arena_width = arena.width;
  layout.arena_height = arena.height;

  const double available_w = width;
  const double available_h = height - layout.header_height;
  layout.scale = std::min(available_w / arena.width, available_h / arena.height);
  const double used_w = arena.width * layout.scale;
  const double used_h = arena.height * layout.scale;
  layout.origin_x = std::floor((available_w - used_w) / 2.0);
  layout.origin_y = layout.header_height + std::floor((available_h - used_h) / 2.0);

  layout.arena.left = static_cast<int>(layout.origin_x);
  layout.arena.top = static_cast<int>(layout.origin_y);
  layout.arena.width =
      std::min(width - layout.arena.left, static_cast<int>(std::ceil(used_w - 1e-9)));
  layout.arena.height =
      std::min(height - layout.arena.top, static_cast<int>(std::ceil(used_h - 1e-9)));
  return layout;
}

FrameLayout zoomed_layout(const FrameLayout& fit, double zoom, Vec2 centre) {
  FrameLayout layout = fit;
  layout.scale = fit.scale * zoom;
  const PixelRect view = fit.view();
  layout.origin_x = view.left + 0.5 * view.width - centre.x * layout.scale;
  layout.origin_y = view.top + 0.5 * view.height - (fit.arena_height - centre.y) * layout.scale;
  const double left = std::max<double>(view.left, std::floor(layout.origin_x));
  const double top = std::max<double>(view.top, std::floor(layout.origin_y));
  const double right = std::min<double>(
      view.left + view.width, std::ceil(layout.origin_x + fit.arena_width * layout.scale));
  const double bottom = std::min<double>(
      view.top + view.height, std::ceil(layout.origin_y + fit.arena_height * layout.scale));
  layout.arena.left = static_cast<int>(left);
  layout.arena.top = static_cast<int>(top);
  layout.arena.width = std::max(0, static_cast<int>(right - left));
  layout.arena.height = std::max(0, static_cast<int>(bottom - top));
  return layout;
}

}  // namespace swarmagg
