#pragma once
// Counter-based random numbers: every draw is a pure function of (replicate key, step,
// agent, purpose). Results therefore do not depend on the order in which agents are
// processed or on how many threads process them, which is what makes runs bit-identical
// for any --threads.
#include <cstdint>

namespace swarmagg {

// SplitMix64's finaliser: a bijective 64-bit mixer with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// What a draw is for; distinct purposes give independent streams.
enum class Draw : std::uint32_t {
  Heading = 1,
  Leave = 2,
  Tumble = 3,
  Placement = 4,
  Model = 5,
  EnclosedLeave = 6,  // the heading of a leaver with neighbours on all sides
};

// The draws of one step: CounterRng::bits and uniform with the step's share of the hash
// done once, for the controllers that draw for every agent of a step.
class StepRng {
 public:
  [[gnu::always_inline]] constexpr std::uint64_t bits(std::uint64_t agent, Draw purpose,
                                                      std::uint64_t extra = 0) const {
    const std::uint64_t h = mix64(step_hash_ ^ (agent * 0xD1B54A32D192ED03ull));
    return mix64(h ^ (static_cast<std::uint64_t>(purpose) << 32) ^ extra);
  }

  // Uniform in [0, 1) with 53 random bits.
  constexpr double uniform(std::uint64_t agent, Draw purpose, std::uint64_t extra = 0) const {
    return static_cast<double>(bits(agent, purpose, extra) >> 11) * 0x1.0p-53;
  }

 private:
  friend class CounterRng;  // CounterRng::at_step is the one way to make one
  constexpr explicit StepRng(std::uint64_t step_hash) : step_hash_(step_hash) {}

  std::uint64_t step_hash_;
};

class CounterRng {
 public:
  constexpr CounterRng() = default;
  constexpr explicit CounterRng(std::uint64_t key) : key_(key) {}

  // The key of replicate `index` of a world seeded with `seed`.
  static constexpr CounterRng for_replicate(std::uint64_t seed, std::uint64_t index) {
    return CounterRng(mix64(mix64(seed) ^ mix64(index + 0x5851F42D4C957F2Dull)));
  }

  constexpr StepRng at_step(std::uint64_t step) const { return StepRng(mix64(key_ ^ step)); }

  constexpr std::uint64_t bits(std::uint64_t step, std::uint64_t agent, Draw purpose,
                               std::uint64_t extra = 0) const {
    return at_step(step).bits(agent, purpose, extra);
  }

  // Uniform in [0, 1) with 53 random bits.
  constexpr double uniform(std::uint64_t step, std::uint64_t agent, Draw purpose,
                           std::uint64_t extra = 0) const {
    return at_step(step).uniform(agent, purpose, extra);
  }

  constexpr std::uint64_t key() const { return key_; }

 private:
  std::uint64_t key_ = 0;
};

}  // namespace swarmagg
