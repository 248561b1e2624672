#pragma once
// Test helper: a PNG decoded to RGB with libpng, and the checks a plot must pass to show
// something: more than two colours, and coloured (curve, bar, point) pixels inside the
// plot's frame, the box gnuplot draws around the data.
#include <png.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <set>
#include <vector>

namespace swarmagg::testing {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, 3 bytes a pixel

  const std::uint8_t* at(int x, int y) const {
    return &rgb[3 * (static_cast<std::size_t>(y) * width + x)];
  }
};

// Empty (width 0) when the file is not a PNG libpng can read.
inline RgbImage read_rgb_png(const std::filesystem::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.c_str())) return {};
  image.format = PNG_FORMAT_RGB;
  RgbImage out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) return {};
  return out;
}

inline std::size_t distinct_colours(const RgbImage& image) {
  std::set<std::array<std::uint8_t, 3>> colours;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
    colours.insert({image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]});
  return colours.size();
}

struct Frame {
  int left = 0, right = 0, top = 0, bottom = 0;
};

// The plot's border: the outermost rows and columns that are dark over at least 40% of
// the image (gnuplot's frame; curves, text and the dotted grid never are).
inline Frame plot_frame(const RgbImage& image) {
  auto dark = [&](int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return p[0] < 80 && p[1] < 80 && p[2] < 80;
  };
  Frame frame{image.width, -1, image.height, -1};
  for (int y = 0; y < image.height; ++y) {
    int count = 0;
    for (int x = 0; x < image.width; ++x) count += dark(x, y);
    if (count > 0.4 * image.width) {
      frame.top = std::min(frame.top, y);
      frame.bottom = std::max(frame.bottom, y);
    }
  }
  for (int x = 0; x < image.width; ++x) {
    int count = 0;
    for (int y = 0; y < image.height; ++y) count += dark(x, y);
    if (count > 0.4 * image.height) {
      frame.left = std::min(frame.left, x);
      frame.right = std::max(frame.right, x);
    }
  }
  return frame;
}

// Pixels strictly inside the frame that are coloured (not white, grey or black).
inline int coloured_pixels_inside(const RgbImage& image, const Frame& frame) {
  int count = 0;
  for (int y = frame.top + 1; y < frame.bottom; ++y) {
    for (int x = frame.left + 1; x < frame.right; ++x) {
      const std::uint8_t* p = image.at(x, y);
      const int high = std::max({p[0], p[1], p[2]}), low = std::min({p[0], p[1], p[2]});
      count += high - low > 40;
    }
  }
  return count;
}

}  // namespace swarmagg::testing
