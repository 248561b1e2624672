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

double wrap(double v, double period) {
  const double w = v - period * std::floor(v / period);
  return w < period ? w : 0.0;  // v slightly below 0 can round up to period
}

Vec2 separation(Vec2 from, Vec2 to, double w, double h, bool torus) {
  Vec2 d = to - from;
  if (torus) {
    d.x -= w * std::round(d.x / w);
    d.y -= h * std::round(d.y / h);
  }
  return d;
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

  wrapped_.resize(n);
  for (std::int32_t i = 0; i < n; ++i) {
    const Vec2 p = snapshot.positions[i];
    wrapped_[i] = torus ? Vec2{wrap(p.x, w), wrap(p.y, h)} : p;
  }

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

  find_links(snapshot, torus);
  for (const auto& [i, j] : link_pairs_) {
    const Vec2 p = wrapped_[i];
    const Vec2 d = separation(p, wrapped_[j], w, h, torus);
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

void FrameSceneBuilder::find_links(const SwarmSnapshot& snapshot, bool torus) {
  link_pairs_.clear();
  if (snapshot.aggregate.empty()) return;
  const WorldSpec& spec = *snapshot.spec;
  const double w = spec.arena.width;
  const double h = spec.arena.height;
  const double s = spec.robots.detection_radius;
  const double s2 = s * s;
  const auto& aggregate = snapshot.aggregate;

  members_.clear();
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(aggregate.size()); ++i) {
    if (aggregate[i] >= 0) members_.push_back(i);
  }
  const auto linked = [&](std::int32_t i, std::int32_t j) {
    return aggregate[i] == aggregate[j] &&
           norm2(separation(wrapped_[i], wrapped_[j], w, h, torus)) <= s2;
  };

  const int nx = std::max(1, static_cast<int>(std::floor(w / s)));
  const int ny = std::max(1, static_cast<int>(std::floor(h / s)));
  if (members_.size() <= 48 || nx < 3 || ny < 3) {
    for (std::size_t a = 0; a < members_.size(); ++a) {
      for (std::size_t b = a + 1; b < members_.size(); ++b) {
        if (linked(members_[a], members_[b])) link_pairs_.emplace_back(members_[a], members_[b]);
      }
    }
    return;
  }

  // Uniform grid with cells at least s wide: partners lie in the 3x3 cells around.
  const auto cell_x = [&](double x) { return std::clamp(static_cast<int>(x / w * nx), 0, nx - 1); };
  const auto cell_y = [&](double y) { return std::clamp(static_cast<int>(y / h * ny), 0, ny - 1); };
  cell_start_.assign(static_cast<std::size_t>(nx) * ny + 1, 0);
  cell_of_.resize(members_.size());
  for (std::size_t m = 0; m < members_.size(); ++m) {
    const Vec2 p = wrapped_[members_[m]];
    cell_of_[m] = cell_y(p.y) * nx + cell_x(p.x);
    ++cell_start_[cell_of_[m] + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
  bucketed_.resize(members_.size());
  for (std::size_t m = 0; m < members_.size(); ++m) {
    bucketed_[cell_fill_[cell_of_[m]]++] = members_[m];
  }
  for (const std::int32_t i : members_) {
    const Vec2 p = wrapped_[i];
    const int cx = cell_x(p.x);
    const int cy = cell_y(p.y);
    for (int dy = -1; dy <= 1; ++dy) {
      int y = cy + dy;
      if (torus) y = (y + ny) % ny;
      if (y < 0 || y >= ny) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        int x = cx + dx;
        if (torus) x = (x + nx) % nx;
        if (x < 0 || x >= nx) continue;
        const int c = y * nx + x;
        for (std::int32_t e = cell_start_[c]; e < cell_start_[c + 1]; ++e) {
          const std::int32_t j = bucketed_[e];
          if (j > i && linked(i, j)) link_pairs_.emplace_back(i, j);
        }
      }
    }
  }
}

}  // namespace swarmagg
