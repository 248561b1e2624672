#include "config/input_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/errors.hpp"

namespace swarmagg {

std::string read_input_file(const std::string& path, const std::string& kind) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error) {
    const bool missing = error == std::errc::no_such_file_or_directory;
    throw InputError(path + ": cannot open the " + kind + " (" +
                     (missing ? std::string("no such file") : error.message()) + ")");
  }
  if (std::filesystem::is_directory(status))
    throw InputError(path + ": is a folder; expected a " + kind + " (YAML)");
  // A pipe (`<(sed ... world.yaml)`) is read to its end, as cat reads it; a device or a
  // socket has no end to read to.
  if (std::filesystem::is_character_file(status) || std::filesystem::is_block_file(status) ||
      std::filesystem::is_socket(status))
    throw InputError(path + ": is a device or a socket, not a file; expected a " + kind +
                     " (YAML)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the " + kind + " (no permission to read it?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the " + kind);
  return text.str();
}

}  // namespace swarmagg
