#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <sys/types.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <optional>
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

// `video FRAMES /dev/full`, run as root, made the system's device a regular file.
bool is_special_file(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::symlink_status(path, error);
  return !error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
         !std::filesystem::is_directory(status) && !std::filesystem::is_symlink(status);
}

void discard_temporary(const std::filesystem::path& temporary) {
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
}

void rename_or_discard(const std::filesystem::path& temporary,
                       const std::filesystem::path& target) {
  if (is_special_file(target)) {
    discard_temporary(temporary);
    throw std::system_error(std::make_error_code(std::errc::invalid_argument),
                            "cannot write " + target.string() +
                                ": it is a device, pipe or socket, which the finished output "
                                "would replace; name a regular file");
  }
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

AtomicFileWriter::AtomicFileWriter(std::filesystem::path target) : target_(std::move(target)) {
  if (target_.has_parent_path()) std::filesystem::create_directories(target_.parent_path());
  temporary_ = temporary_beside(target_);
  file_ = std::fopen(temporary_.c_str(), "wb");
  if (file_ == nullptr) fail("cannot write", target_);
}

AtomicFileWriter::~AtomicFileWriter() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_) discard_temporary(temporary_);
}

void AtomicFileWriter::write(std::string_view piece) {
  if (std::fwrite(piece.data(), 1, piece.size(), file_) != piece.size())
    fail("cannot write", target_);
}

void AtomicFileWriter::finish() {
  const bool flushed = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  const int flush_error = errno;
  const bool closed = std::fclose(file_) == 0;
  const int close_error = errno;
  file_ = nullptr;
  if (!flushed || !closed) fail("cannot write", target_, flushed ? close_error : flush_error);
}

void AtomicFileWriter::commit() {
  if (file_ != nullptr) finish();
  committed_ = true;  // rename_or_discard removes the temporary itself when it fails
  rename_or_discard(temporary_, target_);
}

void write_file_atomic(const std::filesystem::path& target, std::string_view content) {
  AtomicFileWriter file(target);
  file.write(content);
  file.commit();
}

namespace {

// The process id in a name temporary_beside made (".<name>.<pid>.<n>.tmp"), or none.
std::optional<pid_t> writer_of_temporary(const std::string& name) {
  if (!name.starts_with(".") || !name.ends_with(".tmp")) return std::nullopt;
  const std::string stem = name.substr(0, name.size() - 4);
  const std::size_t counter_dot = stem.rfind('.');
  if (counter_dot == std::string::npos || counter_dot == 0) return std::nullopt;
  const std::size_t pid_dot = stem.rfind('.', counter_dot - 1);
  if (pid_dot == std::string::npos || pid_dot == 0) return std::nullopt;
  const std::string pid = stem.substr(pid_dot + 1, counter_dot - pid_dot - 1);
  const std::string counter = stem.substr(counter_dot + 1);
  const auto digits = [](const std::string& text) {
    return !text.empty() && text.size() < 10 &&
           text.find_first_not_of("0123456789") == std::string::npos;
  };
  if (!digits(pid) || !digits(counter)) return std::nullopt;
  return static_cast<pid_t>(std::stol(pid));
}

}  // namespace

std::size_t remove_stale_temporaries(const std::filesystem::path& folder) {
  std::size_t removed = 0;
  std::error_code missing;
  for (const auto& entry : std::filesystem::directory_iterator(folder, missing)) {
    const std::optional<pid_t> writer = writer_of_temporary(entry.path().filename().string());
    // kill(pid, 0) fails with ESRCH only when no such process exists.
    if (!writer || !(::kill(*writer, 0) != 0 && errno == ESRCH)) continue;
    std::error_code ignored;
    // A folder so named holds a killed run's staged frames (render/staged_frames.hpp).
    removed += std::filesystem::remove_all(entry.path(), ignored) > 0 ? 1 : 0;
  }
  return removed;
}

}  // namespace swarmagg
