#pragma once
// The property both fuzz targets check on every world the loader accepts: the resolved
// world (what `validate` prints and every run folder records) loads back, unchanged. A
// world that loads but cannot be written back faithfully would make a run unreproducible.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "core/errors.hpp"

namespace swarmagg::fuzz {

[[noreturn]] inline void fail(const std::string& what, const std::string& text) {
  std::fprintf(stderr, "round trip failed: %s\n--- resolved world ---\n%s\n", what.c_str(),
               text.c_str());
  std::abort();
}

inline void require_round_trip(const WorldSpec& spec) {
  const std::string text = world_to_yaml(spec);
  std::string again;
  try {
    again = world_to_yaml(load_world_text(text, "resolved.yaml"));
  } catch (const InputError& e) {
    fail(std::string("the resolved world does not load: ") + e.what(), text);
  }
  if (again != text) fail("the resolved world loads as a different world:\n" + again, text);
}

}  // namespace swarmagg::fuzz
