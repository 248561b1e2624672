#include "run/initial_placement.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "controllers/controller.hpp"
#include "core/errors.hpp"
#include "geometry/hilbert_curve.hpp"
#include "geometry/pair_finder.hpp"

namespace swarmagg {
namespace {

constexpr double kDegree = 3.141592653589793 / 180.0;
constexpr int kAttemptsPerAgent = 100000;
// From this many agents on, ids follow space (see number_by_space); below it every agent's
// data fits in the core's caches anyway, and numbering by draw order keeps the results of
// small worlds (the paper's) as they were.
constexpr std::size_t kSpatialNumberingFrom = 4096;

// A position on the torus's far edge (x = width) is its near edge: given as such, so that
// both engines and the first recorded row hold it inside [0, width) (the kinematic engine kept
// x = width until the agent moved; Box2D wrapped it at once).
InitialPlacement explicit_placement(const WorldSpec& spec) {
  InitialPlacement result;
  const ArenaGeometry arena = spec.arena.geometry();
  for (const PlacedAgent& a : spec.robots.placement) {
    result.positions.push_back(arena.wrap({a.x, a.y}));
    result.headings.push_back(from_angle(a.heading_deg * kDegree));
  }
  return result;
}

InitialPlacement random_placement(const WorldSpec& spec, const CounterRng& rng) {
  const ArenaGeometry arena = spec.arena.geometry();
  const auto n = static_cast<std::size_t>(spec.robots.count);
  const double r = spec.robots.radius;
  const double margin = spec.arena.topology == Topology::Walls ? r : 0.0;
  const double contact = 2.0 * r;
  PairFinder placed_bodies;
  placed_bodies.reset(arena, contact, n);
  // Free where no placed body is closer than contact (touching is allowed).
  const auto free_at = [&](Vec2 p) {
    bool free = true;
    placed_bodies.for_each_near(p,
                                [&](std::uint32_t, Vec2 d) { free = free && norm(d) >= contact; });
    return free;
  };
  InitialPlacement result;
  result.positions.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    bool placed = false;
    for (std::uint64_t attempt = 0; attempt < kAttemptsPerAgent && !placed; ++attempt) {
      const Vec2 p{margin + (spec.arena.width - 2 * margin) *
                                rng.uniform(0, i, Draw::Placement, 2 * attempt),
                   margin + (spec.arena.height - 2 * margin) *
                                rng.uniform(0, i, Draw::Placement, 2 * attempt + 1)};
      if (!free_at(p)) continue;
      placed_bodies.add(p);
      result.positions.push_back(p);
      placed = true;
    }
    if (!placed) {
      throw InputError(spec.source + ": robots.count: could not place agent " + std::to_string(i) +
                       " of " + std::to_string(n) +
                       " without overlapping another body; use a larger arena or fewer agents");
    }
    result.headings.push_back(random_heading(rng, 0, static_cast<std::uint32_t>(i)));
  }
  return result;
}

// Agents are exchangeable, so which id gets which drawn position is free. Ids in the order
// of a Hilbert curve through cells of the arena (one to two detection radii) put the agents an
// agent perceives at nearby ids, and every range of ids in a compact patch of the arena: the
// per-agent arrays the engine and the controller read for neighbours then stay in cache at any N,
// instead of costing a memory access per neighbour, and so do the data a patch's aggregates touch.
// (Bands of the arena, the order before, kept neighbours near too, but a patch's agents were
// spread over as many bands as it is high: at 10^6 agents a step cost about a sixth more.)
// Headings stay with their ids (they are independent of positions).
void number_by_space(const WorldSpec& spec, std::vector<Vec2>& positions) {
  // Cells of one to two detection radii, as many as the curve's grid has along the arena's
  // longer side: a square arena is covered without cells outside it, where the curve would
  // leave the agents and come back elsewhere.
  const double longer_side = std::max(spec.arena.width, spec.arena.height);
  int order = 0;
  while (order < 31 && std::ldexp(2.0 * spec.robots.detection_radius, order) < longer_side) ++order;
  const double cell = std::ldexp(longer_side, -order);
  const double last_cell = std::ldexp(1.0, order) - 1.0;
  const auto cell_of = [&](double coordinate) {
    return static_cast<std::uint32_t>(std::clamp(std::floor(coordinate / cell), 0.0, last_cell));
  };
  // (curve position, x, draw index) of each agent, sorted once: a total order, so ties
  // cannot reorder.
  struct Key {
    std::uint64_t along_curve;
    double x;
    std::uint32_t index;
    bool operator<(const Key& o) const {
      return along_curve != o.along_curve ? along_curve < o.along_curve
             : x != o.x                   ? x < o.x
                                          : index < o.index;
    }
  };
  std::vector<Key> keys(positions.size());
  for (std::uint32_t i = 0; i < keys.size(); ++i) {
    const Vec2 p = positions[i];
    keys[i] = {hilbert_position(cell_of(p.x), cell_of(p.y), order), p.x, i};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<Vec2> ordered(positions.size());
  for (std::size_t k = 0; k < keys.size(); ++k) ordered[k] = positions[keys[k].index];
  positions.swap(ordered);
}

}  // namespace

InitialPlacement place_agents(const WorldSpec& spec, const CounterRng& rng) {
  if (!spec.robots.random_placement()) return explicit_placement(spec);
  InitialPlacement placement = random_placement(spec, rng);
  if (placement.positions.size() >= kSpatialNumberingFrom)
    number_by_space(spec, placement.positions);
  return placement;
}

}  // namespace swarmagg
