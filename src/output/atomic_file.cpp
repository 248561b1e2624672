#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace swarmagg {
namespace {

[[noreturn]] void fail(const std::string& what, const std::filesystem::path& path) {
  throw std::runtime_error(what + " " + path.string() + ": " + std::strerror(errno));
}

}  // namespace

std::filesystem::path temporary_beside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() /
         ("." + target.filename().string() + "." + std::to_string(::getpid()) + "." +
          std::to_string(counter.fetch_add(1)) + ".tmp");
}

void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target) {
  const int fd = ::open(temporary.c_str(), O_RDONLY);
  if (fd < 0) fail("cannot open", temporary);
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  if (!synced) fail("cannot sync", temporary);
  std::filesystem::rename(temporary, target);
}

void write_file_atomic(const std::filesystem::path& target, std::string_view content) {
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const auto temporary = temporary_beside(target);
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) fail("cannot create", temporary);
  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
  if (std::fclose(file) != 0 || !written || !flushed) {
    std::filesystem::remove(temporary);
    fail("cannot write", temporary);
  }
  std::filesystem::rename(temporary, target);
}

}  // namespace swarmagg
