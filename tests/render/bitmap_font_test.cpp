#include "render/bitmap_font.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace swarmagg {
namespace {

TEST(BitmapFont, EveryDigitAndLetterHasItsOwnGlyph) {
  std::set<std::array<std::uint8_t, kGlyphHeight>> seen;
  const std::string chars = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.,:=-+/()_%#";
  for (const char c : chars) {
    const auto rows = glyph_rows(c);
    bool lit = false;
    for (const auto r : rows) {
      EXPECT_LT(r, 1 << kGlyphWidth) << c;
      lit = lit || r != 0;
    }
    EXPECT_TRUE(lit) << c;
    EXPECT_TRUE(seen.insert(rows).second) << "duplicate glyph for " << c;
  }
  EXPECT_EQ(glyph_rows('n'), glyph_rows('N'));
  EXPECT_EQ(glyph_rows('~'), glyph_rows('?'));
  EXPECT_EQ(glyph_rows(static_cast<char>(200)), glyph_rows('?'));
}

TEST(BitmapFont, DrawsGlyphBitsScaled) {
  const int w = 40;
  const int h = 20;
  std::vector<std::uint8_t> rgba(w * h * 4, 255);
  const Rgba8 ink{10, 20, 30, 255};
  const int end = draw_text(rgba, w, h, 1, 2, 2, ink, "1T");
  EXPECT_EQ(end, 1 + text_width("1T", 2));
  EXPECT_EQ(text_width("1T", 2), (2 * kGlyphAdvance - 1) * 2);
  const auto at = [&](int x, int y) {
    const std::size_t o = (static_cast<std::size_t>(y) * w + x) * 4;
    return Rgba8{rgba[o], rgba[o + 1], rgba[o + 2], rgba[o + 3]};
  };
  const auto one = glyph_rows('1');
  for (int gy = 0; gy < kGlyphHeight; ++gy) {
    for (int gx = 0; gx < kGlyphWidth; ++gx) {
      const bool lit = (one[gy] >> (kGlyphWidth - 1 - gx)) & 1;
      for (int sy = 0; sy < 2; ++sy) {
        for (int sx = 0; sx < 2; ++sx) {
          EXPECT_EQ(at(1 + 2 * gx + sx, 2 + 2 * gy + sy) == ink, lit) << gx << "," << gy;
        }
      }
    }
  }
  // The top bar of the T, the second glyph.
  EXPECT_EQ(at(1 + 2 * kGlyphAdvance, 2), ink);
  EXPECT_EQ(at(0, 0), (Rgba8{255, 255, 255, 255}));
}

TEST(BitmapFont, ClipsAtTheImageEdges) {
  const int w = 8;
  const int h = 8;
  std::vector<std::uint8_t> rgba(w * h * 4, 0);
  draw_text(rgba, w, h, -3, -4, 3, Rgba8{1, 2, 3, 255}, "WWW");
  draw_text(rgba, w, h, 6, 6, 3, Rgba8{1, 2, 3, 255}, "WWW");
  fill_rect(rgba, w, h, -5, -5, 100, 100, Rgba8{9, 9, 9, 255});
  EXPECT_EQ(rgba[(7 * w + 7) * 4], 9);
}

TEST(BitmapFont, BlendsTranslucentRectangles) {
  std::vector<std::uint8_t> rgba(4 * 4 * 4, 255);
  fill_rect(rgba, 4, 4, 0, 0, 2, 2, Rgba8{0, 0, 0, 128});
  EXPECT_EQ(rgba[0], 127);
  EXPECT_EQ(rgba[3], 255);
  EXPECT_EQ(rgba[(3 * 4 + 3) * 4], 255);
}

}  // namespace
}  // namespace swarmagg
