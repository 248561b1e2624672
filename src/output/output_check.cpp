#include "output/output_check.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/made_folders.hpp"

namespace swarmagg {
namespace {

[[noreturn]] void refuse(const std::string& option, const std::filesystem::path& path,
                         const std::string& why) {
  throw InputError(option + " " + path.string() + ": " + why);
}

// The reason in lower case, as it reads in the middle of a sentence.
std::string reason(int error) {
  std::string text = std::strerror(error);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

// The first ancestor of `folder` that exists but is not a folder, if any: a folder cannot be
// made below a file.
std::filesystem::path file_in_the_way(const std::filesystem::path& folder) {
  std::error_code ignored;
  for (std::filesystem::path p = folder; !p.empty() && p != p.parent_path(); p = p.parent_path()) {
    if (std::filesystem::exists(p, ignored) && !std::filesystem::is_directory(p, ignored)) return p;
  }
  return {};
}

// Why no file can be written in `folder` (created if missing), or "" when one can.
std::string folder_problem(const std::filesystem::path& folder) {
  if (folder.empty()) return "an empty path";
  if (const std::filesystem::path file = file_in_the_way(folder); !file.empty()) {
    return file == folder ? "is a file, not a folder (outputs go into a folder)"
                          : file.string() + " is a file, so no folder can be made below it";
  }
  // The folders made for the probe are removed after it: a run refused later (a world the
  // engine rejects) leaves no empty folder, and the writers make them again.
  std::error_code error;
  const MadeFolders made(folder, error);
  if (error) return "cannot create the folder (" + reason(error.value()) + ")";
  const std::filesystem::path probe =
      folder / (".swarmagg-write-test." + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int open_error = errno;
  if (fd >= 0) ::close(fd);
  std::filesystem::remove(probe, error);
  made.remove_if_empty();
  if (fd < 0) return "cannot write in the folder (" + reason(open_error) + ")";
  return "";
}

}  // namespace

void check_output_folder(const std::filesystem::path& folder, const std::string& option) {
  if (const std::string why = folder_problem(folder); !why.empty()) refuse(option, folder, why);
}

void check_output_file(const std::filesystem::path& file, const std::string& option) {
  if (file.empty() || !file.has_filename()) refuse(option, file, "expected a file name");
  std::error_code ignored;
  if (std::filesystem::is_directory(file, ignored)) refuse(option, file, "is a folder, not a file");
  if (is_special_file(file)) {
    refuse(option, file,
           "is a device, pipe or socket: the finished output would replace it; name a regular "
           "file");
  }
  const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
  if (const std::string why = folder_problem(folder); !why.empty())
    refuse(option, file, "its folder " + folder.string() + ": " + why);
}

void refuse_to_replace(const std::filesystem::path& folder, const std::string& earlier,
                       const std::string& replaced) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error) || std::filesystem::is_empty(folder, error))
    return;
  throw InputError(folder.string() + "/ already holds files (" + earlier + "): pass --force to " +
                   "replace " + replaced + ", or --out DIR to write this one elsewhere");
}

}  // namespace swarmagg
