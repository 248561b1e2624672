#pragma once
// A fresh directory under the system temp dir, removed with its content at scope exit. The
// process id in its name keeps concurrent test runs (ctest -j, two checkouts on one machine)
// from deleting each other's outputs.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace swarmagg::testing {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name) {
    path_ = std::filesystem::temp_directory_path() /
            ("swarmagg-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace swarmagg::testing
