#include "render/frame_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "render/bitmap_font.hpp"
#include "render/frame_header.hpp"

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

bool in_scope(OverlayScope scope, std::int32_t agent, std::int32_t selected) {
  return scope == OverlayScope::All || (scope == OverlayScope::Selected && agent == selected);
}

// Widths and radii in pixels, scaled with the frame's text scale.
struct Strokes {
  float ring_line;
  float body_line;
  float link_half;
  float ring_radius;
  float approach_radius;
  float tint_radius;
  float body_radius;
  double extent;  // arena units a shape reaches from its agent's centre
};

Strokes strokes(const WorldSpec& spec, const FrameLayout& layout, const SceneOptions& options) {
  const double k = layout.text_scale;
  Strokes out{};
  out.ring_line = static_cast<float>(std::max(1.0, 0.75 * k));
  out.body_line = static_cast<float>(std::max(1.0, 0.5 * k));
  out.link_half = static_cast<float>(std::max(0.75, 0.5 * k));
  out.ring_radius =
      static_cast<float>(spec.robots.detection_radius * layout.scale) + out.ring_line / 2;
  out.approach_radius =
      static_cast<float>(spec.controller.approach_radius * layout.scale) + out.ring_line / 2;
  out.tint_radius = static_cast<float>(0.5 * spec.robots.detection_radius * layout.scale);
  out.body_radius = std::max(kMinBodyPixels, static_cast<float>(spec.robots.radius * layout.scale));
  double reach = std::max(out.ring_radius, out.body_radius);
  if (options.approach != OverlayScope::None) reach = std::max<double>(reach, out.approach_radius);
  out.extent = (reach + 1.0) / layout.scale;
  return out;
}

}  // namespace

FrameLayout FrameSceneBuilder::layout_for(const FrameLayout& fit, const SceneOptions& options) {
  if (options.fits()) return fit;
  const Vec2 centre = options.centre.value_or(Vec2{fit.arena_width / 2, fit.arena_height / 2});
  return zoomed_layout(fit, options.zoom, centre);
}

Rgba8 FrameSceneBuilder::body_colour(const SwarmSnapshot& snapshot, std::int32_t agent) const {
  const std::int32_t a = snapshot.aggregate.empty() ? -1 : snapshot.aggregate[agent];
  switch (colour_) {
    case ColourMode::State:
      return palette::state_colour(snapshot.states[agent]);
    case ColourMode::Aggregate:
      return a < 0 ? palette::kUnaggregated : palette::aggregate_colour(lowest_member_[a]);
    case ColourMode::Size:
      return palette::size_colour(a < 0 ? 0 : aggregate_size_[a],
                                  static_cast<std::int32_t>(snapshot.positions.size()));
  }
  return palette::kText;
}

const FrameScene& FrameSceneBuilder::build(const SwarmSnapshot& snapshot, const FrameLayout& fit,
                                           const SceneOptions& options, const SceneExtras& extras) {
  if (snapshot.spec == nullptr) throw std::invalid_argument("render: snapshot without a spec");
  if (snapshot.states.size() != snapshot.positions.size() ||
      (!snapshot.aggregate.empty() && snapshot.aggregate.size() != snapshot.positions.size())) {
    throw std::invalid_argument("render: snapshot arrays of different lengths");
  }
  const WorldSpec& spec = *snapshot.spec;
  const FrameLayout layout = layout_for(fit, options);
  const bool torus = spec.arena.topology == Topology::Torus;
  const bool ghosts = torus && options.ghosts;
  const double w = spec.arena.width;
  const double h = spec.arena.height;
  const double k = layout.text_scale;
  const auto n = static_cast<std::int32_t>(snapshot.positions.size());
  const auto aggregate_of = [&](std::int32_t i) {
    return snapshot.aggregate.empty() ? -1 : snapshot.aggregate[i];
  };
  const Strokes st = strokes(spec, layout, options);
  colour_ = options.colour;

  scene_.tints.clear();
  scene_.rings.clear();
  scene_.links.clear();
  scene_.bodies.clear();
  scene_.marks.clear();
  scene_.walls.clear();
  scene_.rects.clear();
  scene_.labels.clear();

  const ArenaGeometry arena = spec.arena.geometry();
  wrapped_.resize(n);
  for (std::int32_t i = 0; i < n; ++i) wrapped_[i] = arena.wrap(snapshot.positions[i]);

  lowest_member_.assign(std::max(snapshot.noa, 0), std::numeric_limits<std::int32_t>::max());
  aggregate_size_.assign(lowest_member_.size(), 0);
  for (std::int32_t i = 0; i < n; ++i) {
    const auto a = aggregate_of(i);
    if (a < 0) continue;
    if (static_cast<std::size_t>(a) >= lowest_member_.size()) {
      lowest_member_.resize(a + 1, std::numeric_limits<std::int32_t>::max());
      aggregate_size_.resize(a + 1, 0);
    }
    lowest_member_[a] = std::min(lowest_member_[a], i);
    ++aggregate_size_[a];
  }

  const Rgba8 no_fill{0, 0, 0, 0};
  const float mark_line = static_cast<float>(std::max(2.0, 1.5 * k));
  for (std::int32_t i = 0; i < n; ++i) {
    const Vec2 p = wrapped_[i];
    const auto a = aggregate_of(i);
    const Offsets offsets = copies(p, st.extent, w, h, ghosts);
    for (int c = 0; c < offsets.count; ++c) {
      const Vec2 q = layout.to_pixel(p + offsets.values[c]);
      const auto x = static_cast<float>(q.x);
      const auto y = static_cast<float>(q.y);
      if (a >= 0 && options.tints) {
        const Rgba8 tint = palette::aggregate_tint(lowest_member_[a]);
        scene_.tints.push_back({x, y, st.tint_radius, 0.0f, tint, tint});
      }
      if (in_scope(options.detection, i, options.selected)) {
        scene_.rings.push_back({x, y, st.ring_radius, st.ring_line, no_fill, palette::kDetection});
      }
      if (in_scope(options.approach, i, options.selected)) {
        scene_.rings.push_back(
            {x, y, st.approach_radius, st.ring_line, no_fill, palette::kApproachRing});
      }
      scene_.bodies.push_back(
          {x, y, st.body_radius, st.body_line, body_colour(snapshot, i), palette::kBodyOutline});
      if (i == options.selected) {
        scene_.marks.push_back(
            {x, y, st.body_radius + 2 * mark_line, mark_line, no_fill, palette::kSelection});
      }
    }
  }

  if (options.trails) add_trails(snapshot, layout, extras, st.link_half);
  add_pair_segments(snapshot, layout, options, st.extent, st.link_half);

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
  add_frame_header(scene_, fit, snapshot);
  add_selection_label(layout, options);
  return scene_;
}

// The selected agent's id beside its mark (each copy), where it falls inside the view.
void FrameSceneBuilder::add_selection_label(const FrameLayout& layout,
                                            const SceneOptions& options) {
  if (options.selected < 0) return;
  const std::string text = std::to_string(options.selected);
  const int k = layout.text_scale;
  const PixelRect view = layout.view();
  for (const CircleInstance& mark : scene_.marks) {
    const int x = static_cast<int>(std::lround(mark.x + mark.radius + k));
    const int y = static_cast<int>(std::lround(mark.y - mark.radius - kGlyphHeight * k));
    if (x < view.left || y < view.top || x + text_width(text, k) > view.left + view.width ||
        y + kGlyphHeight * k > view.top + view.height) {
      continue;
    }
    scene_.labels.push_back({x, y, k, palette::kSelection, text});
  }
}

void draw_scene_text(std::span<std::uint8_t> rgba, int width, int height, const FrameScene& scene) {
  for (const FilledRect& r : scene.rects)
    fill_rect(rgba, width, height, r.x, r.y, r.width, r.height, r.colour);
  for (const TextLabel& l : scene.labels)
    draw_text(rgba, width, height, l.x, l.y, l.scale, l.colour, l.text);
}

// Segments between agents: every neighbour pair, the aggregate links, the touching pairs, in
// that order, each drawn from the first agent of the pair (and its seam copies).
void FrameSceneBuilder::add_pair_segments(const SwarmSnapshot& snapshot, const FrameLayout& layout,
                                          const SceneOptions& options, double extent,
                                          float half_width) {
  const WorldSpec& spec = *snapshot.spec;
  const ArenaGeometry arena = spec.arena.geometry();
  const bool ghosts = arena.torus() && options.ghosts;
  const auto add = [&](const Link& link, Rgba8 colour, float half) {
    const Vec2 p = wrapped_[link.i];
    const Offsets offsets = copies(p, extent, spec.arena.width, spec.arena.height, ghosts);
    for (int c = 0; c < offsets.count; ++c) {
      const Vec2 a = layout.to_pixel(p + offsets.values[c]);
      const Vec2 b = layout.to_pixel(p + link.d + offsets.values[c]);
      scene_.links.push_back({static_cast<float>(a.x), static_cast<float>(a.y),
                              static_cast<float>(b.x), static_cast<float>(b.y), half, colour});
    }
  };

  near_pairs_.clear();
  const double touching = 2.0 * spec.robots.radius * (1.0 + 1e-9);
  if (options.neighbour_links || options.contacts) {
    const double radius = options.neighbour_links ? spec.robots.detection_radius : touching;
    all_finder_.reset(arena, radius, wrapped_.size());
    for (const Vec2& p : wrapped_) all_finder_.add(p);
    all_finder_.for_each_pair([&](std::uint32_t i, std::uint32_t j, Vec2 d) {
      near_pairs_.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), d});
    });
    std::sort(near_pairs_.begin(), near_pairs_.end(),
              [](const Link& a, const Link& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  }
  if (options.neighbour_links) {
    for (const Link& link : near_pairs_) add(link, palette::kNeighbourLink, half_width / 2);
  }
  if (options.links) {
    find_links(snapshot, arena);
    for (const Link& link : link_pairs_) add(link, palette::kLink, half_width);
  }
  if (options.contacts) {
    for (const Link& link : near_pairs_) {
      if (norm(link.d) <= touching) add(link, palette::kContact, 2 * half_width);
    }
  }
}

// A trail joins each agent's consecutive past positions (minimum image, so a wrap does not
// draw a line across the arena).
void FrameSceneBuilder::add_trails(const SwarmSnapshot& snapshot, const FrameLayout& layout,
                                   const SceneExtras& extras, float half_width) {
  const std::size_t n = snapshot.positions.size();
  if (extras.trail_frames < 2 || extras.trail.size() != n * extras.trail_frames) return;
  const ArenaGeometry arena = snapshot.spec->arena.geometry();
  for (std::size_t i = 0; i < n; ++i) {
    for (int f = 1; f < extras.trail_frames; ++f) {
      const Vec2 from = arena.wrap(extras.trail[(f - 1) * n + i]);
      const Vec2 to = from + arena.displacement(from, extras.trail[f * n + i]);
      const Vec2 a = layout.to_pixel(from);
      const Vec2 b = layout.to_pixel(to);
      scene_.links.push_back({static_cast<float>(a.x), static_cast<float>(a.y),
                              static_cast<float>(b.x), static_cast<float>(b.y), half_width / 2,
                              palette::kTrail});
    }
  }
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

std::int32_t pick_agent(const SwarmSnapshot& snapshot, const FrameLayout& layout, Vec2 pixel,
                        float tolerance) {
  if (snapshot.spec == nullptr) return -1;
  const ArenaGeometry arena = snapshot.spec->arena.geometry();
  const Vec2 point = layout.to_arena(pixel);
  if (!arena.torus() &&
      (point.x < 0 || point.y < 0 || point.x > arena.width() || point.y > arena.height())) {
    return -1;
  }
  const double body = std::max<double>(kMinBodyPixels, snapshot.spec->robots.radius * layout.scale);
  const double reach = (body + tolerance) / layout.scale;
  std::int32_t best = -1;
  double best_distance = reach;
  for (std::size_t i = 0; i < snapshot.positions.size(); ++i) {
    const double d = arena.distance(arena.wrap(snapshot.positions[i]), arena.wrap(point));
    if (d <= best_distance) {
      best_distance = d;
      best = static_cast<std::int32_t>(i);
    }
  }
  return best;
}

}  // namespace swarmagg
