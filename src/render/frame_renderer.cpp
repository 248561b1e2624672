#include "render/frame_renderer.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/frame_scene.hpp"
#include "render/instanced_shapes.hpp"
#include "render/osmesa_context.hpp"
#include "render/render_size.hpp"

namespace swarmagg {
namespace {

void clear(Rgba8 c) {
  glClearColor(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

// Binds a context for the scope of a frame and releases it at the end, even on error.
class Binding {
 public:
  Binding(OsMesaContext& context, std::span<std::uint8_t> target) : context_(context) {
    context_.bind(target);
  }
  ~Binding() { context_.release(); }
  Binding(const Binding&) = delete;
  Binding& operator=(const Binding&) = delete;

 private:
  OsMesaContext& context_;
};

}  // namespace

struct FrameRenderer::Impl {
  Impl(int width, int height)
      : context(width, height), pixels(static_cast<std::size_t>(width) * height * 4) {
    Binding binding(context, pixels);
    shapes = std::make_unique<InstancedShapes>();
    shapes->set_viewport(width, height);
  }
  ~Impl() {
    Binding binding(context, pixels);
    shapes.reset();
  }

  // Draws straight into `target` (width * height * 4 bytes): no copy.
  void render(const SwarmSnapshot& snapshot, std::span<std::uint8_t> target,
              const SceneOptions& options = {}, const SceneExtras& extras = {}) {
    if (snapshot.spec == nullptr) throw std::invalid_argument("render: snapshot without a spec");
    const FrameLayout fit =
        make_frame_layout(context.width(), context.height(), snapshot.spec->arena);
    const FrameScene& scene = builder.build(snapshot, fit, options, extras);
    const FrameLayout layout = FrameSceneBuilder::layout_for(fit, options);
    {
      Binding binding(context, target);
      using Layer = InstancedShapes::Layer;
      glDisable(GL_SCISSOR_TEST);
      clear(palette::kMargin);
      // Pixel rows map to GL window rows one to one (see instanced_shapes.cpp).
      glEnable(GL_SCISSOR_TEST);
      glScissor(layout.arena.left, layout.arena.top, layout.arena.width, layout.arena.height);
      clear(palette::kArena);
      shapes->draw(Layer::Tints, scene.tints);
      shapes->draw(Layer::Rings, scene.rings);
      shapes->draw(Layer::Links, scene.links);
      shapes->draw(Layer::Bodies, scene.bodies);
      shapes->draw(Layer::Marks, scene.marks);
      // Fitted, the walls may reach past the arena's pixels; zoomed, they stay below the header.
      if (options.fits()) {
        glDisable(GL_SCISSOR_TEST);
      } else {
        const PixelRect view = layout.view();
        glScissor(view.left, view.top, view.width, view.height);
      }
      shapes->draw(Layer::Walls, scene.walls);
      glDisable(GL_SCISSOR_TEST);
      glFinish();
      if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw std::runtime_error("render: OpenGL error " + std::to_string(error));
      }
    }
    draw_scene_text(target, layout.width, layout.height, scene);
  }

  OsMesaContext context;
  std::vector<std::uint8_t> pixels;  // the frame render(snapshot) returns
  std::unique_ptr<InstancedShapes> shapes;
  FrameSceneBuilder builder;
};

FrameRenderer::FrameRenderer(int width, int height) {
  validate_render_size(width, height);
  impl_ = std::make_unique<Impl>(width, height);
}

FrameRenderer::~FrameRenderer() = default;
FrameRenderer::FrameRenderer(FrameRenderer&&) noexcept = default;
FrameRenderer& FrameRenderer::operator=(FrameRenderer&&) noexcept = default;

int FrameRenderer::width() const {
  return impl_->context.width();
}
int FrameRenderer::height() const {
  return impl_->context.height();
}

FrameLayout FrameRenderer::layout(const ArenaSpec& arena) const {
  return make_frame_layout(width(), height(), arena);
}

std::span<const std::uint8_t> FrameRenderer::render(const SwarmSnapshot& snapshot) {
  impl_->render(snapshot, impl_->pixels);
  return impl_->pixels;
}

void FrameRenderer::render(const SwarmSnapshot& snapshot, std::span<std::uint8_t> rgba) {
  render(snapshot, rgba, SceneOptions{});
}

void FrameRenderer::render(const SwarmSnapshot& snapshot, std::span<std::uint8_t> rgba,
                           const SceneOptions& options, const SceneExtras& extras) {
  if (rgba.size() != static_cast<std::size_t>(width()) * height() * 4) {
    throw std::invalid_argument("render: output buffer of " + std::to_string(rgba.size()) +
                                " bytes for a " + std::to_string(width()) + "x" +
                                std::to_string(height()) + " frame");
  }
  impl_->render(snapshot, rgba, options, extras);
}

}  // namespace swarmagg
