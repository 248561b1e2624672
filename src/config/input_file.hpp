#pragma once
// The text of a file the user names as input (a world, a sweep), refused with a message that
// names the path and what is wrong before anything is read: a folder, a device (reading
// /dev/zero grew without end), a path that does not resolve. A pipe is read to its end.
#include <string>

namespace swarmagg {

// `kind` names the file in messages, e.g. "world file". Throws InputError.
std::string read_input_file(const std::string& path, const std::string& kind);

}  // namespace swarmagg
