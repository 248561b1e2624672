// libFuzzer target: `--set` overrides. Each line of the input is one `key.path=value`
// assignment, applied to a small valid world exactly as `swarmagg run --set ...` applies
// them (load_world_text -> apply_override for each, then the cross-key checks). As for the
// world file: accepted and written back faithfully, or an InputError; nothing else.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "fuzz/round_trip.hpp"

namespace {

constexpr const char* kBaseWorld =
    "name: base\narena: {width: 60, height: 60}\nrobots: {count: 20}\nrun: {duration: 100}\n";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  swarmagg::WorldSpec spec;
  try {
    spec = swarmagg::load_world_text(kBaseWorld, "base.yaml", lines_of(text));
  } catch (const swarmagg::InputError&) {
    return 0;
  }
  swarmagg::fuzz::require_round_trip(spec);
  return 0;
}
