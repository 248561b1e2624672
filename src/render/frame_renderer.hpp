#pragma once
// Off-screen drawing of one SwarmSnapshot into RGBA pixels (OSMesa; no display needed):
// arena floor, aggregate tints, detection circles, aggregate links, agent bodies coloured
// by state, torus wrap copies, and a header with time, step, NOA and a legend (see
// frame_scene.hpp for the layers, palette.hpp for the colours, frame_layout.hpp for the
// geometry). The same snapshot always gives the same bytes.
//
// A renderer owns a GL context; it may be used from any thread, one thread at a time.
#include <cstdint>
#include <memory>
#include <span>

#include "config/world_spec.hpp"
#include "observers/swarm_snapshot.hpp"
#include "render/frame_layout.hpp"
#include "render/scene_options.hpp"

namespace swarmagg {

class FrameRenderer {
 public:
  // Throws InputError for sizes outside render_size.hpp's bounds, std::runtime_error if no
  // OpenGL context can be created. The first frame pays the shader compilation.
  FrameRenderer(int width, int height);
  ~FrameRenderer();
  FrameRenderer(FrameRenderer&&) noexcept;
  FrameRenderer& operator=(FrameRenderer&&) noexcept;

  int width() const;
  int height() const;
  FrameLayout layout(const ArenaSpec& arena) const;

  // Draws `snapshot`; returns width * height * 4 bytes, RGBA, rows top-down, valid until the
  // next render() or the renderer's end.
  std::span<const std::uint8_t> render(const SwarmSnapshot& snapshot);
  // The same, copied into `rgba`, which must hold exactly width * height * 4 bytes.
  void render(const SwarmSnapshot& snapshot, std::span<std::uint8_t> rgba);
  // Draws the scene the view options describe (frame_scene.hpp) into `rgba`; the default
  // options draw the frame above.
  void render(const SwarmSnapshot& snapshot, std::span<std::uint8_t> rgba,
              const SceneOptions& options, const SceneExtras& extras = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swarmagg
