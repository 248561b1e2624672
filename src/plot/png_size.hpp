#pragma once
// Reads a PNG's pixel size from its header (signature, then the IHDR chunk), so callers
// and tests can check that a plot is a valid PNG of the requested size without decoding it.
#include <filesystem>
#include <optional>

namespace swarmagg {

struct PngSize {
  int width = 0;
  int height = 0;
};

// The size, or nothing when the file is missing or does not start like a PNG.
std::optional<PngSize> png_size(const std::filesystem::path& file);

}  // namespace swarmagg
