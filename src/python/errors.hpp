#pragma once
// How the library's errors reach Python. An InputError raised while reading a world or
// sweep file (or applying `set`) becomes swarmagg.WorldError, a ValueError carrying the
// CLI's message (file, line, key, expectation); any other InputError, a bad argument, is a
// plain ValueError; an interrupted run is KeyboardInterrupt; a file the system would not
// write or read (std::system_error, std::filesystem errors too) is the matching OSError.
#include <functional>

#include "core/errors.hpp"

namespace swarmagg::python {

// An InputError about an input file, thrown again as such.
class FileInputError : public InputError {
 public:
  using InputError::InputError;
};

// Calls `read`, turning its InputError into a FileInputError.
template <typename Read>
auto reading_file(Read read) -> decltype(read()) {
  try {
    return read();
  } catch (const FileInputError&) {
    throw;
  } catch (const InputError& e) {
    throw FileInputError(e.what());
  }
}

}  // namespace swarmagg::python
