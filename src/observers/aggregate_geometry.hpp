#pragma once
// The shape of an aggregate (docs/models.md): size m, torus-aware centroid c, outer radius
// R1 = max_i |x_i - c| + r, the mean distance from each member to its nearest fellow member
// (its member spacing), and its rim count.
//
// Rim member: a member with fewer than 6 fellow members within 1.2 x spacing. An interior
// disc of a hexagonal packing at that spacing has exactly 6 (its second shell lies at
// sqrt(3) x spacing); the factor 1.2 leaves room for a packing that is not exact. A
// hexagonal cluster of 7, 19 and 37 has a rim of 6, 12 and 18.
//
// The centroid is the mean of the members' minimum-image displacements from one member,
// so an aggregate must span less than half the arena's side (any aggregate of a world
// where aggregation means anything does). An aggregate of 64 members or more finds each
// member's fellows in a grid of its members (O(m log m), the same values bit for bit); a
// smaller one compares every pair. Meant for the recorded states and the attempts, not for
// every agent of every step.
#include <memory>
#include <span>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/neighbour_lists.hpp"
#include "core/vec2.hpp"
#include "geometry/arena_geometry.hpp"
#include "observers/aggregate_members.hpp"

namespace swarmagg {

// The spacing packed members keep: controller.compaction.spacing (2r, touching, by default).
double packing_spacing(const WorldSpec& spec);

struct RimRule {
  static constexpr double kReachFactor = 1.2;
  static constexpr int kInteriorFellows = 6;
  double reach = kReachFactor * 2.0;  // fellow members counted within this centre distance
  static RimRule for_spacing(double spacing) { return {kReachFactor * spacing}; }
  bool on_rim(int fellows_within_reach) const { return fellows_within_reach < kInteriorFellows; }
};

// Everything a shape is measured against: the arena (for distances), r, the rim rule.
struct ShapeRules {
  ArenaGeometry arena;
  double body_radius = 1.0;
  RimRule rim;
  static ShapeRules for_world(const WorldSpec& spec);
};

struct AggregateShape {
  int size = 0;
  Vec2 centroid;
  double outer_radius = 0.0;         // R1
  double mean_member_spacing = 0.0;  // mean over members of the distance to the nearest fellow
  int rim = 0;
};

// One member among its fellow members (the others of `members`).
struct MemberSurroundings {
  double nearest_fellow = 0.0;   // centre distance; infinity when it has no fellow
  int fellows_within_reach = 0;  // within the rim rule's reach
};
MemberSurroundings member_surroundings(AgentId agent, std::span<const AgentId> members,
                                       std::span<const Vec2> positions, const ShapeRules& rules);

class MemberGrid;  // aggregate_geometry.cpp

// Which members of one aggregate stand on its rim, for many of them: from a grid of its members
// when it has kGridFrom members or more (as measure_aggregate does), each answer the pairwise
// scan's exactly; else by the scan. One attempt at a time scanned all m members: a packed
// aggregate of 4 x 10^4 with a few dozen leavers a step spent most of the run there.
class RimCounter {
 public:
  RimCounter(std::span<const AgentId> members, std::span<const Vec2> positions,
             const ShapeRules& rules);
  ~RimCounter();
  RimCounter(const RimCounter&) = delete;
  RimCounter& operator=(const RimCounter&) = delete;

  bool on_rim(AgentId member) const;

 private:
  std::span<const AgentId> members_;
  std::span<const Vec2> positions_;
  const ShapeRules& rules_;
  std::unique_ptr<MemberGrid> grid_;  // for kGridFrom members or more, when usable
};

// The shape of one aggregate of at least two members.
AggregateShape measure_aggregate(std::span<const AgentId> members, std::span<const Vec2> positions,
                                 const ShapeRules& rules);
// Every aggregate's shape, by aggregate index.
std::vector<AggregateShape> measure_aggregates(const AggregateMembers& members,
                                               std::span<const Vec2> positions,
                                               const ShapeRules& rules);

}  // namespace swarmagg
