#pragma once
// Cumulative aggregation events of one replicate (SPEC 4).
#include <cstdint>

namespace swarmagg {

struct EventCounts {
  std::uint64_t creations = 0;     // two searching agents met and formed an aggregate
  std::uint64_t growths = 0;       // a searching agent joined an aggregate
  std::uint64_t dissipations = 0;  // an aggregate of two lost an agent
  std::uint64_t shrinks = 0;       // an aggregate of three or more lost an agent
  std::uint64_t encounters = 0;    // first contacts within s of any pair
};

}  // namespace swarmagg
