#include "render/frame_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace swarmagg {
namespace {

// Translations (in arena units) under which a shape reaching `extent` from `p` is visible.
struct Offsets {
  std::array<Vec2, 9> values;
  int count = 0;
};

Offsets copies(Vec2 p, double extent, double w, double h, bool torus) {
  std::array<double, 3> xs{0.0, 0.0, 0.0};
  std::array<double, 3> ys{0.0, 0.0, 0.0};
  int nx = 1;
  int ny = 1;
  if (torus) {
    if (p.x < extent) xs[nx++] = w;
    if (p.x > w - extent) xs[nx++] = -w;
    if (p.y < extent) ys[ny++] = h;
    if (p.y > h - extent) ys[ny++] = -h;
  }
  Offsets out;
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) out.values[out.count++] = Vec2{xs[ix], ys[iy]};
  }
  return out;
}

}  // namespace

const FrameScene& FrameSceneBuilder::build(const SwarmSnapshot& snapshot,
                                           const FrameLayout& layout) {
  if (snapshot.spec == nullptr) throw std::invalid_argument("render: snapshot without a spec");
  if (snapshot.states.size() != snapshot.positions.size() ||
      (!snapshot.aggregate.empty() && snapshot.aggregate.size() != snapshot.positions.size())) {
    throw std::invalid_argument("render: snapshot arrays of different lengths");
  }
  const WorldSpec& spec = *snapshot.spec;
  const bool torus = spec.arena.topology == Topology::Torus;
  const double w = spec.arena.width;
  const double h = spec.arena.height;
  const double s = spec.robots.detection_radius;
  const double r = spec.robots.radius;
  const double k = layout.text_scale;
  const auto n = static_cast<std::int32_t>(snapshot.positions.size());
  const auto aggregate_of = [&](std::int32_t i) {
    return snapshot.aggregate.empty() ? -1 : snapshot.aggregate[i];
  };

  const float ring_line = static_cast<float>(std::max(1.0, 0.75 * k));
  const float body_line = static_cast<float>(std::max(1.0, 0.5 * k));
  const float link_half = static_cast<float>(std::max(0.75, 0.5 * k));
  const float ring_radius = static_cast<float>(s * layout.scale) + ring_line / 2;
  const float tint_radius = static_cast<float>(0.5 * s * layout.scale);
  const float body_radius = std::max(kMinBodyPixels, static_cast<float>(r * layout.scale));
  const double extent =
      (std::max({static_cast<double>(ring_radius), static_cast<double>(body_radius)}) + 1.0) /
      layout.scale;

  scene_.tints.clear();
  scene_.rings.clear();
  scene_.links.clear();
  scene_.bodies.clear();
  scene_.walls.clear();

  const ArenaGeometry arena = spec.arena.geometry();
  wrapped_.resize(n);
  for (std::int32_t i = 0; i < n; ++i) wrapped_[i] = arena.wrap(snapshot.positions[i]);

  lowest_member_.assign(std::max(snapshot.noa, 0), std::numeric_limits<std::int32_t>::max());
  for (std::int32_t i = 0; i < n; ++i) {
    const auto a = aggregate_of(i);
    if (a < 0) continue;
    if (static_cast<std::size_t>(a) >= lowest_member_.size()) {
      lowest_member_.resize(a + 1, std::numeric_limits<std::int32_t>::max());
    }
    lowest_member_[a] = std::min(lowest_member_[a], i);
  }

  for (std::int32_t i = 0; i < n; ++i) {
    const Vec2 p = wrapped_[i];
    const auto a = aggregate_of(i);
    const Offsets offsets = copies(p, extent, w, h, torus);
    for (int c = 0; c < offsets.count; ++c) {
      const Vec2 q = layout.to_pixel(p + offsets.values[c]);
      const auto x = static_cast<float>(q.x);
      const auto y = static_cast<float>(q.y);
      if (a >= 0) {
        const Rgba8 tint = palette::aggregate_tint(lowest_member_[a]);
        scene_.tints.push_back({x, y, tint_radius, 0.0f, tint, tint});
      }
      scene_.rings.push_back(
          {x, y, ring_radius, ring_line, Rgba8{0, 0, 0, 0}, palette::kDetection});
      scene_.bodies.push_back({x, y, body_radius, body_line,
                               palette::state_colour(snapshot.states[i]), palette::kBodyOutline});
    }
  }

  find_links(snapshot, arena);
  for (const auto& [i, j, d] : link_pairs_) {
    const Vec2 p = wrapped_[i];
    const Offsets offsets = copies(p, extent, w, h, torus);
    for (int c = 0; c < offsets.count; ++c) {
      const Vec2 a = layout.to_pixel(p + offsets.values[c]);
      const Vec2 b = layout.to_pixel(p + d + offsets.values[c]);
      scene_.links.push_back({static_cast<float>(a.x), static_cast<float>(a.y),
                              static_cast<float>(b.x), static_cast<float>(b.y), link_half,
                              palette::kLink});
    }
  }

  if (!torus) {
    const float half = static_cast<float>(std::max(1.0, k));
    const std::array<Vec2, 4> corners{layout.to_pixel({0, 0}), layout.to_pixel({w, 0}),
                                      layout.to_pixel({w, h}), layout.to_pixel({0, h})};
    for (int c = 0; c < 4; ++c) {
      const Vec2 a = corners[c];
      const Vec2 b = corners[(c + 1) % 4];
      scene_.walls.push_back({static_cast<float>(a.x), static_cast<float>(a.y),
                              static_cast<float>(b.x), static_cast<float>(b.y), half,
                              palette::kWall});
    }
  }
  return scene_;
}

// Links join members of one aggregate within s of each other; drawn in (i, j) order.
void FrameSceneBuilder::find_links(const SwarmSnapshot& snapshot, const ArenaGeometry& arena) {
  link_pairs_.clear();
  if (snapshot.aggregate.empty()) return;
  const auto& aggregate = snapshot.aggregate;
  members_.clear();
  const auto aggregated =
      std::count_if(aggregate.begin(), aggregate.end(), [](std::int32_t a) { return a >= 0; });
  members_finder_.reset(arena, snapshot.spec->robots.detection_radius,
                        static_cast<std::size_t>(aggregated));
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(aggregate.size()); ++i) {
    if (aggregate[i] < 0) continue;
    members_.push_back(i);
    members_finder_.add(wrapped_[i]);
  }
  members_finder_.for_each_pair([&](std::uint32_t a, std::uint32_t b, Vec2 d) {
    const std::int32_t i = members_[a], j = members_[b];
    if (aggregate[i] == aggregate[j]) link_pairs_.push_back({i, j, d});
  });
  std::sort(link_pairs_.begin(), link_pairs_.end(),
            [](const Link& a, const Link& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
}

}  // namespace swarmagg
