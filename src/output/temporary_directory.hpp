#pragma once
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace swarmagg {

// The system's temporary directory as POSIX and Python's tempfile read it: $TMPDIR when set
// and not empty, else /tmp (std::filesystem::temp_directory_path fails on an empty $TMPDIR).
inline std::filesystem::path temporary_directory(std::error_code& error) {
  const char* tmpdir = std::getenv("TMPDIR");
  const std::filesystem::path folder = tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp";
  error.clear();
  if (!std::filesystem::is_directory(folder, error) && !error)
    error = std::make_error_code(std::errc::not_a_directory);
  return folder;
}

}  // namespace swarmagg
