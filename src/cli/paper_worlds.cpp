#include "cli/paper_worlds.hpp"

#include <filesystem>
#include <system_error>

#include "core/errors.hpp"

namespace swarmagg::cli {
namespace {

constexpr const char* kCloneWorlds = "worlds/paper";

// PREFIX/share/swarmagg/worlds/paper for the binary in PREFIX/bin, found from the binary
// itself: `make install PREFIX=...` copies a build made for any prefix.
std::filesystem::path installed_worlds() {
  std::error_code error;
  const std::filesystem::path binary = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  return binary.parent_path().parent_path() / "share" / "swarmagg" / "worlds" / "paper";
}

}  // namespace

std::string paper_worlds_folder(const std::string& given) {
  if (!given.empty()) {
    if (std::filesystem::is_directory(given)) return given;
    throw InputError("--worlds: " + given + ": no such folder (expected the paper's worlds)");
  }
  if (std::filesystem::is_directory(kCloneWorlds)) return kCloneWorlds;
  const std::filesystem::path installed = installed_worlds();
  if (!installed.empty() && std::filesystem::is_directory(installed)) return installed.string();
  throw InputError(
      std::string("no paper worlds in ") + kCloneWorlds +
      " (run from the repository's root) nor beside the binary (" +
      (installed.empty() ? std::string("share/swarmagg/worlds/paper") : installed.string()) +
      ", where make install puts them); give their folder with --worlds");
}

std::string paper_worlds_default_help() {
  return std::string("default ") + kCloneWorlds +
         " if there, else the installed PREFIX/share/swarmagg/worlds/paper of a binary in "
         "PREFIX/bin";
}

}  // namespace swarmagg::cli
