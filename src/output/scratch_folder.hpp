#pragma once
// A private folder of its own under the system's temporary directory, removed with everything
// in it when the object goes. Named by mkdtemp, so several threads or processes never share one.
#include <stdlib.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "output/temporary_directory.hpp"

namespace swarmagg {

class ScratchFolder {
 public:
  // `prefix` starts the folder's name (six random characters follow).
  // Throws std::filesystem::filesystem_error (an OSError in Python) naming the temporary
  // directory ($TMPDIR, else /tmp) when it is missing or refuses the folder.
  explicit ScratchFolder(const std::string& prefix) {
    std::error_code error;
    const std::filesystem::path temporary = temporary_directory(error);
    if (error) {
      const char* tmpdir = std::getenv("TMPDIR");
      throw std::filesystem::filesystem_error(
          "no temporary directory for a scratch folder ($TMPDIR=" +
              std::string(tmpdir ? tmpdir : "(unset), /tmp") + ")",
          error);
    }
    std::string name = (temporary / (prefix + "-XXXXXX")).string();
    if (mkdtemp(name.data()) == nullptr) {
      throw std::filesystem::filesystem_error(
          "cannot create a scratch folder in the temporary directory ($TMPDIR or /tmp)", temporary,
          std::error_code(errno, std::generic_category()));
    }
    path_ = name;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace swarmagg
