#pragma once
// A fresh directory under the system temp dir, removed with its content at scope exit; its
// random name keeps concurrent test runs (ctest -j, two checkouts on one machine) and threads
// from deleting each other's outputs.
#include <string>

#include "output/scratch_folder.hpp"

namespace swarmagg::testing {

class ScratchDir : public ScratchFolder {
 public:
  explicit ScratchDir(const std::string& name) : ScratchFolder("swarmagg-" + name) {}
};

}  // namespace swarmagg::testing
