#include "run/state_hash.hpp"

#include <cstdio>
#include <span>

#include "run/replicate.hpp"

namespace swarmagg {
namespace {

// FNV-1a: stable across compilers and runs, unlike std::hash.
class Fnv1a {
 public:
  template <typename T>
  void add(std::span<const T> values) {
    for (const std::byte b : std::as_bytes(values)) {
      hash_ ^= static_cast<std::uint64_t>(b);
      hash_ *= 1099511628211ull;
    }
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace

std::uint64_t state_hash(const Replicate& replicate) {
  Fnv1a hash;
  hash.add(replicate.engine().positions());
  hash.add(std::span<const Vec2>(replicate.swarm().heading));
  hash.add(std::span<const AgentState>(replicate.swarm().state));
  return hash.value();
}

std::string state_hash_text(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace swarmagg
