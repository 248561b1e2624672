#include "observers/aggregate_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace swarmagg {

double packing_spacing(const WorldSpec& spec) {
  return spec.compaction_spacing();
}

ShapeRules ShapeRules::for_world(const WorldSpec& spec) {
  return {spec.arena.geometry(), spec.robots.radius, RimRule::for_spacing(packing_spacing(spec))};
}

namespace {

// One fellow member more in `around`, the member's surroundings so far.
void add_fellow(MemberSurroundings& around, AgentId agent, AgentId fellow,
                std::span<const Vec2> positions, const ShapeRules& rules) {
  const double d = rules.arena.distance(positions[agent], positions[fellow]);
  around.nearest_fellow = std::min(around.nearest_fellow, d);
  around.fellows_within_reach += d <= rules.rim.reach;
}

}  // namespace

MemberSurroundings member_surroundings(AgentId agent, std::span<const AgentId> members,
                                       std::span<const Vec2> positions, const ShapeRules& rules) {
  MemberSurroundings around{std::numeric_limits<double>::infinity(), 0};
  for (const AgentId j : members) {
    if (j != agent) add_fellow(around, agent, j, positions, rules);
  }
  return around;
}

namespace {

// From this many members on, each member's fellows are looked up in a grid of the members
// instead of among all of them: the pairwise scan is O(m^2), hours for the one aggregate of a
// densely packed swarm of 3 x 10^5 agents.
constexpr std::size_t kGridFrom = 64;

}  // namespace

// The members sorted into square-ish cells at least the rim reach wide: every fellow within
// that reach of a member lies in the member's cell or one of the 8 around it (wrapped on a
// torus), so those hold all the fellows it counts and, whenever one is that close, its nearest.
class MemberGrid {
 public:
  // Empty (unusable) when the arena is fewer than 3 cells across: the 9 cells around a
  // member would then repeat.
  MemberGrid(std::span<const AgentId> members, std::span<const Vec2> positions,
             const ShapeRules& rules)
      : arena_(rules.arena),
        columns_(cells_across(arena_.width(), rules.rim.reach)),
        rows_(cells_across(arena_.height(), rules.rim.reach)) {
    if (!usable()) return;
    entries_.reserve(members.size());
    for (const AgentId j : members) entries_.push_back({cell_of(positions[j]), j});
    std::sort(entries_.begin(), entries_.end());
  }
  bool usable() const { return columns_ >= 3 && rows_ >= 3; }

  MemberSurroundings around(AgentId agent, std::span<const Vec2> positions,
                            const ShapeRules& rules) const {
    MemberSurroundings result{std::numeric_limits<double>::infinity(), 0};
    const std::int64_t cell = cell_of(positions[agent]);
    const std::int64_t column = cell % columns_, row = cell / columns_;
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const std::int64_t c = neighbour(column + dx, columns_), r = neighbour(row + dy, rows_);
        if (c < 0 || r < 0) continue;
        const Entry first{r * columns_ + c, 0};
        for (auto e = std::lower_bound(entries_.begin(), entries_.end(), first);
             e != entries_.end() && e->cell == first.cell; ++e) {
          if (e->member != agent) add_fellow(result, agent, e->member, positions, rules);
        }
      }
    }
    return result;
  }

 private:
  struct Entry {
    std::int64_t cell;
    AgentId member;
    bool operator<(const Entry& o) const {
      return cell != o.cell ? cell < o.cell : member < o.member;
    }
  };
  // Cells a millionth wider than the reach, so that rounding in cell_of cannot put two
  // members within the reach two cells apart.
  static std::int64_t cells_across(double side, double reach) {
    return static_cast<std::int64_t>(std::floor(side / (reach * (1.0 + 1e-6))));
  }
  // The cell index `k` of a row or column of `count` cells: wrapped on a torus, -1 beyond a
  // wall.
  std::int64_t neighbour(std::int64_t k, std::int64_t count) const {
    if (arena_.torus()) return (k + count) % count;
    return k < 0 || k >= count ? -1 : k;
  }
  std::int64_t cell_of(Vec2 p) const {
    const auto index = [](double coordinate, double side, std::int64_t count) {
      const auto k = static_cast<std::int64_t>(std::floor(coordinate / side * count));
      return std::clamp<std::int64_t>(k, 0, count - 1);
    };
    return index(p.y, arena_.height(), rows_) * columns_ + index(p.x, arena_.width(), columns_);
  }

  ArenaGeometry arena_;
  std::int64_t columns_, rows_;
  std::vector<Entry> entries_;
};

RimCounter::RimCounter(std::span<const AgentId> members, std::span<const Vec2> positions,
                       const ShapeRules& rules)
    : members_(members), positions_(positions), rules_(rules) {
  if (members.size() < kGridFrom) return;
  grid_ = std::make_unique<MemberGrid>(members, positions, rules);
  if (!grid_->usable()) grid_.reset();
}

RimCounter::~RimCounter() = default;

// Every fellow within the reach lies in the 9 cells around the member, so the grid counts
// them all (its nearest fellow, which measure_aggregate also needs, may lie beyond).
bool RimCounter::on_rim(AgentId member) const {
  const MemberSurroundings around = grid_
                                        ? grid_->around(member, positions_, rules_)
                                        : member_surroundings(member, members_, positions_, rules_);
  return rules_.rim.on_rim(around.fellows_within_reach);
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
  std::optional<MemberGrid> grid;
  if (members.size() >= kGridFrom) grid.emplace(members, positions, rules);
  // The grid's answer is the scan's exactly, whenever the nearest fellow lies within the
  // reach (a member farther from all others than that is scanned).
  const auto surroundings = [&](AgentId i) {
    if (grid && grid->usable()) {
      const MemberSurroundings near = grid->around(i, positions, rules);
      if (near.nearest_fellow <= rules.rim.reach) return near;
    }
    return member_surroundings(i, members, positions, rules);
  };
  double farthest = 0.0;
  double nearest_sum = 0.0;
  for (const AgentId i : members) {
    farthest = std::max(farthest, arena.distance(shape.centroid, positions[i]));
    const MemberSurroundings around = surroundings(i);
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
