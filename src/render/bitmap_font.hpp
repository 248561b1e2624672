#pragma once
// A built-in 5x7 bitmap font (digits, upper-case letters, some punctuation; lower case is
// drawn as upper case, anything else as '?') for writing labels straight into top-down
// RGBA pixels, so frames need no font library. Glyphs are magnified by an integer scale.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "render/palette.hpp"

namespace swarmagg {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;  // glyph plus one column of space
inline constexpr int kTextPadding = 3;   // around a line of text, in unscaled pixels

// Rows top to bottom; bit 4 is the leftmost column.
std::array<std::uint8_t, kGlyphHeight> glyph_rows(char c);

int text_width(std::string_view text, int scale);

// Pixels outside the image are clipped. Returns the x just after the text.
int draw_text(std::span<std::uint8_t> rgba, int width, int height, int x, int y, int scale,
              Rgba8 colour, std::string_view text);

void fill_rect(std::span<std::uint8_t> rgba, int width, int height, int x, int y, int w, int h,
               Rgba8 colour);

}  // namespace swarmagg
