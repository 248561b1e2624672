#pragma once
// Bad input (a world file, an override, a command-line value) is an InputError: the CLI
// prints its message and exits 2. Anything else that goes wrong exits 1.
#include <stdexcept>
#include <string>

namespace swarmagg {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace swarmagg
