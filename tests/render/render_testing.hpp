#pragma once
// Helpers for the render tests: a world built in code, snapshots with agents at chosen
// places, pixel access, PNG reading (libpng); scratch directories come from
// testing/scratch_dir.hpp.
#include <png.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "core/agent_state.hpp"
#include "observers/swarm_snapshot.hpp"
#include "render/frame_layout.hpp"
#include "render/palette.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg::testing {

inline WorldSpec tiny_world(double width = 40.0, double height = 40.0,
                            Topology topology = Topology::Torus) {
  WorldSpec spec;
  spec.name = "render-test";
  spec.arena.width = width;
  spec.arena.height = height;
  spec.arena.topology = topology;
  spec.robots.radius = 1.0;
  spec.robots.detection_radius = 4.0;
  spec.render.width = 200;
  spec.render.height = 200;
  return spec;
}

// Owns the arrays a SwarmSnapshot points into.
struct Swarm {
  const WorldSpec* spec = nullptr;
  std::vector<Vec2> positions;
  std::vector<AgentState> states;
  std::vector<std::int32_t> aggregate;
  int noa = 0;
  std::int64_t step = 0;
  double time = 0.0;

  void add(double x, double y, AgentState state = AgentState::Go, std::int32_t agg = -1) {
    positions.push_back({x, y});
    states.push_back(state);
    aggregate.push_back(agg);
    noa = std::max(noa, agg + 1);
  }
  SwarmSnapshot snapshot() const {
    SwarmSnapshot s;
    s.spec = spec;
    s.step = step;
    s.time = time;
    s.positions = positions;
    s.states = states;
    s.aggregate = aggregate;
    s.noa = noa;
    return s;
  }
};

// n agents at uniform random places (fixed seed); a fraction `waiting` of them in WAIT,
// grouped into aggregates of 5 agents packed 2 units apart.
inline Swarm random_swarm(const WorldSpec& spec, int n, double waiting, unsigned seed = 7) {
  Swarm swarm;
  swarm.spec = &spec;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(0.0, spec.arena.width);
  std::uniform_real_distribution<double> y(0.0, spec.arena.height);
  const int grouped = static_cast<int>(n * waiting) / 5 * 5;
  for (int a = 0; a < grouped / 5; ++a) {
    const double cx = x(rng);
    const double cy = y(rng);
    for (int m = 0; m < 5; ++m) {
      swarm.add(cx + 2.0 * (m % 3), cy + 2.0 * (m / 3), AgentState::Wait, a);
    }
  }
  const std::array<AgentState, 3> moving{AgentState::Go, AgentState::Leave, AgentState::Approach};
  for (int i = grouped; i < n; ++i) swarm.add(x(rng), y(rng), moving[i % 3]);
  swarm.step = 12345;
  swarm.time = 1234.5;
  return swarm;
}

inline Rgba8 pixel(std::span<const std::uint8_t> rgba, int width, int col, int row) {
  const std::size_t o = (static_cast<std::size_t>(row) * width + col) * 4;
  return {rgba[o], rgba[o + 1], rgba[o + 2], rgba[o + 3]};
}

// The pixel containing an arena point.
inline Rgba8 pixel_at(std::span<const std::uint8_t> rgba, const FrameLayout& layout, Vec2 p) {
  const Vec2 q = layout.to_pixel(p);
  return pixel(rgba, layout.width, static_cast<int>(q.x), static_cast<int>(q.y));
}

inline int distance(Rgba8 a, Rgba8 b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) + std::abs(a.a - b.a);
}

// `top` blended over an opaque `bottom` with top's alpha.
inline Rgba8 over(Rgba8 top, Rgba8 bottom) {
  const auto mix = [&](int t, int b) {
    return static_cast<std::uint8_t>((t * top.a + b * (255 - top.a) + 127) / 255);
  };
  return {mix(top.r, bottom.r), mix(top.g, bottom.g), mix(top.b, bottom.b), 255};
}

inline std::string describe(Rgba8 c) {
  return "(" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + "," +
         std::to_string(c.a) + ")";
}

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

// Decodes any PNG into RGBA8 with libpng's simplified API.
inline Image read_png(const std::filesystem::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    throw std::runtime_error("cannot read " + path.string() + ": " + image.message);
  }
  image.format = PNG_FORMAT_RGBA;
  Image out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.rgba.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr)) {
    png_image_free(&image);
    throw std::runtime_error("cannot decode " + path.string() + ": " + image.message);
  }
  return out;
}

}  // namespace swarmagg::testing
