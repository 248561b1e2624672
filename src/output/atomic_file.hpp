#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so an
// interrupted run leaves either the previous file or the complete new one, never half.
#include <filesystem>
#include <string_view>

namespace swarmagg {

void write_file_atomic(const std::filesystem::path& target, std::string_view content);

// For outputs that a library writes itself (HDF5): a fresh hidden temporary path beside
// `target` (".<name>.<pid>.<n>.tmp"), and, once the file there is complete and closed,
// commit_temporary() syncs it to disk and renames it over `target`.
std::filesystem::path temporary_beside(const std::filesystem::path& target);
void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target);

}  // namespace swarmagg
