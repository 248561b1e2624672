#include "run/state_hash.hpp"

#include <bit>
#include <cstdio>

namespace swarmagg {
namespace {

constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

void mix_byte(std::uint64_t& hash, std::uint8_t byte) {
  hash ^= byte;
  hash *= kFnvPrime;
}

void mix_double(std::uint64_t& hash, double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  for (int shift = 0; shift < 64; shift += 8)
    mix_byte(hash, static_cast<std::uint8_t>(bits >> shift));
}

}  // namespace

std::uint64_t state_hash(const Replicate& replicate) {
  std::uint64_t hash = kFnvOffset;
  const auto positions = replicate.engine().positions();
  const SwarmState& swarm = replicate.swarm();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    mix_double(hash, positions[i].x);
    mix_double(hash, positions[i].y);
    mix_double(hash, swarm.heading[i].x);
    mix_double(hash, swarm.heading[i].y);
    mix_byte(hash, static_cast<std::uint8_t>(swarm.state[i]));
  }
  return hash;
}

std::string state_hash_text(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace swarmagg
