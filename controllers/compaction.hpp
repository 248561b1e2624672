#pragma once
// docs/controllers.md, "Compaction", for every controller whose waiting agents close up their
// aggregate (Bayindir's, Soysal's, the neighbour-count controller): the rule read from the world,
// the spring velocity of one waiting agent, and the threshold below which a leaver counts as
// enclosed. Each controller decides who its members are; the arithmetic lives here once.
#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/neighbour_lists.hpp"

namespace swarmagg {

// A waiting agent moves under F = sum_j (d_ij - spacing) u_ij from the waiting members of its
// aggregate it perceives, at min(v, gain |F|), standing below tolerance.
struct CompactionRule {
  bool enabled = false;
  double spacing = 2.0;     // u
  double gain = 1.0;        // per tu
  double tolerance = 0.05;  // u
};

// controller.compaction.* of the world (spacing resolved to 2r when unset).
CompactionRule compaction_rule(const WorldSpec& spec);
// Those keys' paths, for the registrations' ControllerCatalogEntry::shared_keys.
std::vector<std::string> compaction_keys();

// A leaver counts as enclosed when the vectors to the agents it perceives (s = 2 spacing)
// sum to less than this fraction of their lengths. In hexagonal packs at spacing 2r the
// fraction is 0.50 on a straight rim and 0.66 to 0.72 on the rim of a 19-pack, against 0 at
// the centre, 0.23 one row inside a straight rim and 0.37 one ring inside a 19-pack's rim.
// Whether an agent counts as enclosed changes only its heading: the bodies around it decide
// whether it gets out. Without compaction aggregates are loose chains, and only an exactly
// zero sum counts (fraction 0).
constexpr double kEnclosedFraction = 0.4;

inline double enclosed_fraction(const CompactionRule& rule) {
  return rule.enabled ? kEnclosedFraction : 0.0;
}

// Adds one member's share of the spring force: a pull when it stands farther than `spacing`,
// a push when nearer; none from a member at the agent's very centre (no direction).
inline void add_spring_force(const CompactionRule& rule, const Neighbour& member, Vec2& force) {
  if (member.distance <= 0.0) return;
  force += member.offset * ((member.distance - rule.spacing) / member.distance);
}

// The velocity a net spring force of norm `magnitude` asks for: at most `speed`, exactly zero
// below the tolerance.
inline Vec2 spring_velocity(const CompactionRule& rule, Vec2 force, double magnitude,
                            double speed) {
  if (magnitude < rule.tolerance || magnitude <= 0.0) return {};
  return force * (std::min(speed, rule.gain * magnitude) / magnitude);
}

// A squared norm below which norm() of a force is certainly under `tolerance` (0 when the
// tolerance is not positive), so that most waiting agents, which stand, skip the square
// root; at or above it spring_velocity's exact test decides. sqrt is correctly rounded, hence
// monotone, so every squared norm below one whose root is under the tolerance has one too.
double standing_norm2(double tolerance);

// The spring force on an agent from the neighbours within `radius` (nearest first) that
// `is_member(id)` accepts (waiting members of its aggregate, or its partner), turned into a
// velocity of at most `speed`; exactly zero when the net force is below the tolerance.
template <class IsMember>
Vec2 compaction_velocity(const CompactionRule& rule, std::span<const Neighbour> neighbours,
                         double radius, double speed, IsMember is_member) {
  Vec2 force;
  for (const Neighbour& nb : neighbours) {
    if (nb.distance > radius) break;
    if (is_member(nb.id)) add_spring_force(rule, nb, force);
  }
  return spring_velocity(rule, force, norm(force), speed);
}

}  // namespace swarmagg
