#pragma once
// What each Box2D fixture of the engine stands for. Every agent body carries, per periodic
// image, a solid disc (radius r) and one or two sensor discs; walls are static boxes. The
// role and the agent are packed into the fixture's user data, and collision categories keep
// each kind of fixture meeting only its own kind (a sensor never pairs with a solid disc).
#include <box2d/box2d.h>

#include <cstdint>

#include "control_interface/neighbour_lists.hpp"

namespace swarmagg::box2d {

enum class FixtureRole : std::uint8_t {
  Solid = 0,   // the body disc, radius r
  Detect = 1,  // sensor of radius s/2: two of them touch when the centres are within s
  Sense = 2,   // sensor of radius R/2 for the sensing radius R > s (Soysal's approach radius)
  Wall = 3,    // a static wall box (walled arenas)
};

enum class WallSide : std::uint8_t { Left = 0, Right = 1, Bottom = 2, Top = 3 };

// Collision categories: a fixture meets another only if each one's mask has the other's
// category. The signal rule of MotionCommand::blocked_by is applied on top (contact filter).
constexpr std::uint16_t kSolidCategory = 0x0001;
constexpr std::uint16_t kDetectCategory = 0x0002;
constexpr std::uint16_t kSenseCategory = 0x0004;
constexpr std::uint16_t kWallCategory = 0x0008;

struct FixtureTag {
  AgentId agent = 0;  // for walls: the WallSide
  FixtureRole role = FixtureRole::Solid;
};

constexpr std::uintptr_t encode_tag(FixtureTag tag) {
  return (static_cast<std::uintptr_t>(tag.agent) << 2) | static_cast<std::uintptr_t>(tag.role);
}

constexpr FixtureTag decode_tag(std::uintptr_t bits) {
  return {static_cast<AgentId>(bits >> 2), static_cast<FixtureRole>(bits & 3u)};
}

inline FixtureTag tag_of(b2Fixture* fixture) {
  return decode_tag(fixture->GetUserData().pointer);
}

inline b2Filter filter_for(FixtureRole role) {
  b2Filter filter;
  switch (role) {
    case FixtureRole::Solid:
      filter.categoryBits = kSolidCategory;
      filter.maskBits = kSolidCategory | kWallCategory;
      break;
    case FixtureRole::Detect:
      filter.categoryBits = kDetectCategory;
      filter.maskBits = kDetectCategory;
      break;
    case FixtureRole::Sense:
      filter.categoryBits = kSenseCategory;
      filter.maskBits = kSenseCategory;
      break;
    case FixtureRole::Wall:
      filter.categoryBits = kWallCategory;
      filter.maskBits = kSolidCategory;
      break;
  }
  return filter;
}

}  // namespace swarmagg::box2d
