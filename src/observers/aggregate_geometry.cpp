#include "observers/aggregate_geometry.hpp"

#include <algorithm>
#include <limits>

namespace swarmagg {

double packing_spacing(const WorldSpec& spec) {
  return spec.compaction_spacing();
}

ShapeRules ShapeRules::for_world(const WorldSpec& spec) {
  return {spec.arena.geometry(), spec.robots.radius,
          RimRule::for_spacing(packing_spacing(spec))};
}

MemberSurroundings member_surroundings(AgentId agent, std::span<const AgentId> members,
                                       std::span<const Vec2> positions, const ShapeRules& rules) {
  MemberSurroundings around{std::numeric_limits<double>::infinity(), 0};
  for (const AgentId j : members) {
    if (j == agent) continue;
    const double d = rules.arena.distance(positions[agent], positions[j]);
    around.nearest_fellow = std::min(around.nearest_fellow, d);
    around.fellows_within_reach += d <= rules.rim.reach;
  }
  return around;
}

AggregateShape measure_aggregate(std::span<const AgentId> members, std::span<const Vec2> positions,
                                 const ShapeRules& rules) {
  const ArenaGeometry& arena = rules.arena;
  AggregateShape shape;
  shape.size = static_cast<int>(members.size());
  const Vec2 reference = positions[members.front()];
  Vec2 sum;
  for (const AgentId j : members) sum += arena.displacement(reference, positions[j]);
  shape.centroid = arena.wrap(reference + sum * (1.0 / static_cast<double>(members.size())));
  double farthest = 0.0;
  double nearest_sum = 0.0;
  for (const AgentId i : members) {
    farthest = std::max(farthest, arena.distance(shape.centroid, positions[i]));
    const MemberSurroundings around = member_surroundings(i, members, positions, rules);
    nearest_sum += around.nearest_fellow;
    shape.rim += rules.rim.on_rim(around.fellows_within_reach);
  }
  shape.outer_radius = farthest + rules.body_radius;
  shape.mean_member_spacing = nearest_sum / static_cast<double>(members.size());
  return shape;
}

std::vector<AggregateShape> measure_aggregates(const AggregateMembers& members,
                                               std::span<const Vec2> positions,
                                               const ShapeRules& rules) {
  std::vector<AggregateShape> shapes;
  shapes.reserve(static_cast<std::size_t>(members.count()));
  for (int k = 0; k < members.count(); ++k)
    shapes.push_back(measure_aggregate(members.of(k), positions, rules));
  return shapes;
}

}  // namespace swarmagg
