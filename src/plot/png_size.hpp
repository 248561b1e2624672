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

// Whether the file is a whole PNG: a PNG's start, and its last chunk the empty IEND (a file
// cut short by a full disk lacks it).
bool png_complete(const std::filesystem::path& file);

}  // namespace swarmagg
