#include "sweep/sweep_seed.hpp"

#include <algorithm>
#include <charconv>

#include "core/rng.hpp"

namespace swarmagg {

namespace {

template <typename T>
bool parses_as(const std::string& text, T& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

// A number's identity is its value, written by std::to_chars' shortest round-trip form,
// which the C++ standard fixes: the seed must not follow later changes to how worlds
// print numbers (format_number), or old sweeps would silently get new seeds.
std::string identity_text(const std::string& value) {
  long long whole = 0;
  double real = 0.0;
  if (parses_as(value, whole) || !parses_as(value, real)) return value;
  char buffer[64];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, real).ptr);
}

}  // namespace

std::string canonical_point_text(std::vector<Assignment> assignments) {
  std::sort(assignments.begin(), assignments.end());
  std::string text;
  for (const auto& [key, value] : assignments) text += key + "=" + identity_text(value) + "\n";
  return text;
}

std::uint64_t text_hash(const std::string& text) {
  std::uint64_t hash = 0xCBF29CE484222325ull;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001B3ull;
  }
  return hash;
}

std::uint64_t sweep_run_seed(std::uint64_t sweep_seed, const std::vector<Assignment>& point,
                             int replicate) {
  // mix64 between the parts keeps seeds of neighbouring points and replicates unrelated.
  const std::uint64_t point_key = mix64(text_hash(canonical_point_text(point)));
  const std::uint64_t replicate_key =
      mix64(static_cast<std::uint64_t>(replicate) + 0x2545F4914F6CDD1Dull);
  return mix64(mix64(sweep_seed) ^ point_key ^ mix64(replicate_key));
}

}  // namespace swarmagg
