// libFuzzer target: any bytes as a world file. The loader must either accept the world (and
// then write it back faithfully) or refuse it with an InputError; any other exception, a
// crash, a sanitizer report or a hang is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "fuzz/round_trip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  swarmagg::WorldSpec spec;
  try {
    spec = swarmagg::load_world_text(text, "fuzz.yaml");
  } catch (const swarmagg::InputError&) {
    return 0;
  }
  swarmagg::fuzz::require_round_trip(spec);
  return 0;
}
