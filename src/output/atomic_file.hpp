#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so an
// interrupted run leaves either the previous file or the complete new one, never half.
#include <filesystem>
#include <string_view>

namespace swarmagg {

void write_file_atomic(const std::filesystem::path& target, std::string_view content);

}  // namespace swarmagg
