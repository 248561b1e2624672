#include "render/render_size.hpp"

#include <charconv>
#include <string>

#include "core/errors.hpp"

namespace swarmagg {

void validate_render_size(int width, int height) {
  auto ok = [](int side) { return side >= kMinRenderSide && side <= kMaxRenderSide; };
  if (!ok(width) || !ok(height)) {
    throw InputError("render size " + std::to_string(width) + "x" + std::to_string(height) +
                     ": each side must be between " + std::to_string(kMinRenderSide) + " and " +
                     std::to_string(kMaxRenderSide) + " pixels");
  }
}

RenderSize parse_render_size(std::string_view text) {
  const auto bad = [&] {
    return InputError("render size '" + std::string(text) +
                      "': expected WIDTHxHEIGHT in pixels, e.g. 800x800");
  };
  const auto x = text.find_first_of("xX");
  if (x == std::string_view::npos) throw bad();
  RenderSize size;
  const auto parse = [&](std::string_view part, int& value) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (part.empty() || error != std::errc() || end != part.data() + part.size()) throw bad();
  };
  parse(text.substr(0, x), size.width);
  parse(text.substr(x + 1), size.height);
  validate_render_size(size.width, size.height);
  return size;
}

}  // namespace swarmagg
