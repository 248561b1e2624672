#pragma once
// PNG encoding (libpng) of top-down RGBA8 pixels, written atomically: into a temporary file
// beside the target, then renamed over it, so a reader never sees half a frame (not fsync'ed:
// frames are cheap to redo, a sync per frame is not). Fully opaque images are stored as RGB.
#include <cstdint>
#include <filesystem>
#include <span>

namespace swarmagg {

// compression_level: zlib 0 (none, fastest) .. 9 (smallest); 1 is a good default for frames.
// Throws InputError for a level outside 0..9, std::invalid_argument when rgba does not hold
// width * height * 4 bytes, std::runtime_error when the file cannot be written.
void write_png(const std::filesystem::path& target, int width, int height,
               std::span<const std::uint8_t> rgba, int compression_level);

}  // namespace swarmagg
