#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <string>
#include <system_error>

namespace swarmagg {
namespace {

// Errors name the output, not its temporary (which is gone by then).
[[noreturn]] void fail(const std::string& what, const std::filesystem::path& target,
                       int error = errno) {
  throw std::system_error(error, std::generic_category(), what + " " + target.string());
}

}  // namespace

void discard_temporary(const std::filesystem::path& temporary) {
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
}

void rename_or_discard(const std::filesystem::path& temporary,
                       const std::filesystem::path& target) {
  std::error_code error;
  std::filesystem::rename(temporary, target, error);
  if (!error) return;
  discard_temporary(temporary);
  throw std::system_error(error, "cannot write " + target.string());
}

std::filesystem::path temporary_beside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() /
         ("." + target.filename().string() + "." + std::to_string(::getpid()) + "." +
          std::to_string(counter.fetch_add(1)) + ".tmp");
}

void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target) {
  const int fd = ::open(temporary.c_str(), O_RDONLY);
  if (fd < 0) fail("cannot write", target);
  const bool synced = ::fsync(fd) == 0;
  const int sync_error = errno;
  ::close(fd);
  if (!synced) {
    discard_temporary(temporary);
    fail("cannot write", target, sync_error);
  }
  rename_or_discard(temporary, target);
}

void write_file_atomic(const std::filesystem::path& target, std::string_view content) {
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const auto temporary = temporary_beside(target);
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) fail("cannot write", target);
  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
  const int write_error = errno;
  if (std::fclose(file) != 0 || !written || !flushed) {
    const int error = written && flushed ? errno : write_error;
    discard_temporary(temporary);
    fail("cannot write", target, error);
  }
  rename_or_discard(temporary, target);
}

}  // namespace swarmagg
