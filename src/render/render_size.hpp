#pragma once
// Frame sizes: the bounds a renderer accepts and the "WIDTHxHEIGHT" text form of
// --render-size. Both throw InputError, since sizes come from the user.
#include <string_view>

namespace swarmagg {

struct RenderSize {
  int width = 800;
  int height = 800;
  friend bool operator==(const RenderSize&, const RenderSize&) = default;
};

inline constexpr int kMinRenderSide = 32;
inline constexpr int kMaxRenderSide = 8192;

void validate_render_size(int width, int height);
RenderSize parse_render_size(std::string_view text);  // "800x600" -> {800, 600}

}  // namespace swarmagg
