#pragma once
// The colours of a rendered frame. Agent states use the Okabe-Ito palette, which stays
// distinguishable under the common colour-vision deficiencies; docs/rendering.md's legend quotes
// these values. Aggregates are shaded with light tints keyed by their lowest member index,
// so an aggregate keeps its tint from frame to frame while that member stays in it.
#include <array>
#include <cstdint>

#include "core/agent_state.hpp"

namespace swarmagg {

struct Rgba8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  std::uint8_t a = 255;
  friend constexpr bool operator==(Rgba8, Rgba8) = default;
};

namespace palette {

inline constexpr Rgba8 kGo{0, 114, 178, 255};          // blue #0072B2
inline constexpr Rgba8 kWait{213, 94, 0, 255};         // vermillion #D55E00
inline constexpr Rgba8 kLeave{0, 158, 115, 255};       // bluish green #009E73
inline constexpr Rgba8 kApproach{204, 121, 167, 255};  // reddish purple #CC79A7

inline constexpr Rgba8 kArena{255, 255, 255, 255};   // arena floor
inline constexpr Rgba8 kMargin{224, 224, 224, 255};  // outside the arena, header band
inline constexpr Rgba8 kText{32, 32, 32, 255};
inline constexpr Rgba8 kBodyOutline{32, 32, 32, 220};
inline constexpr Rgba8 kDetection{0, 0, 0, 96};  // detection circle, blended over the floor
inline constexpr Rgba8 kLink{48, 48, 48, 200};   // aggregate members within s of each other
inline constexpr Rgba8 kWall{32, 32, 32, 255};   // walls topology only

inline constexpr std::array<Rgba8, 8> kAggregateTints{{
    {198, 222, 242, 255},  // light blue
    {250, 236, 184, 255},  // light yellow
    {200, 236, 212, 255},  // light green
    {228, 212, 240, 255},  // light lilac
    {196, 238, 238, 255},  // light cyan
    {236, 228, 210, 255},  // light sand
    {216, 222, 232, 255},  // light slate
    {228, 236, 190, 255},  // light olive
}};

constexpr Rgba8 state_colour(AgentState s) {
  switch (s) {
    case AgentState::Go:
      return kGo;
    case AgentState::Wait:
      return kWait;
    case AgentState::Leave:
      return kLeave;
    case AgentState::Approach:
      return kApproach;
  }
  return kText;
}

// Bodies coloured by aggregate: saturated hues keyed like the tints; agents in none are grey.
inline constexpr Rgba8 kUnaggregated{170, 170, 170, 255};
inline constexpr std::array<Rgba8, 8> kAggregateColours{{
    {0, 114, 178, 255},    // blue
    {230, 159, 0, 255},    // orange
    {0, 158, 115, 255},    // bluish green
    {204, 121, 167, 255},  // reddish purple
    {86, 180, 233, 255},   // sky blue
    {213, 94, 0, 255},     // vermillion
    {120, 94, 240, 255},   // violet
    {140, 140, 0, 255},    // olive
}};
inline constexpr Rgba8 kSelection{0, 0, 0, 255};  // ring around the selected agent
inline constexpr Rgba8 kApproachRing{204, 121, 167, 160};
inline constexpr Rgba8 kNeighbourLink{0, 114, 178, 150};
inline constexpr Rgba8 kContact{213, 0, 0, 230};
inline constexpr Rgba8 kTrail{90, 90, 90, 110};

// Which of the eight tints (and body colours) an aggregate gets, by its lowest member (Knuth's
// multiplicative hash).
constexpr std::size_t aggregate_key(std::int32_t lowest_member) {
  return ((static_cast<std::uint32_t>(lowest_member) * 2654435761u) >> 16) % kAggregateTints.size();
}

// The tint of the aggregate whose lowest member index is `lowest_member`.
constexpr Rgba8 aggregate_tint(std::int32_t lowest_member) {
  return kAggregateTints[aggregate_key(lowest_member)];
}

constexpr Rgba8 aggregate_colour(std::int32_t lowest_member) {
  return kAggregateColours[aggregate_key(lowest_member)];
}

// Bodies coloured by the size of their aggregate: grey outside one, then from light yellow
// (pairs) to dark purple (the whole swarm of `agents`), on a logarithmic scale of size.
constexpr Rgba8 size_colour(std::int32_t size, std::int32_t agents) {
  if (size < 2) return kUnaggregated;
  constexpr std::array<Rgba8, 5> ramp{{{253, 231, 37, 255},
                                       {94, 201, 98, 255},
                                       {33, 145, 140, 255},
                                       {59, 82, 139, 255},
                                       {68, 1, 84, 255}}};
  // A log2 bucket: 2, 3-4, 5-8, 9-16, more; small swarms reach the last bucket sooner.
  int bucket = 0;
  for (std::int32_t s = size - 1; s > 1 && bucket < 4; s >>= 1) ++bucket;
  if (agents > 1 && size >= agents) bucket = 4;
  return ramp[bucket];
}

}  // namespace palette
}  // namespace swarmagg
