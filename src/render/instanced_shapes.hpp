#pragma once
// Draws FrameScene layers with one instanced call each: every circle or segment is a quad
// whose fragment shader computes coverage from the distance to the shape (anti-aliased over
// one pixel), so the cost is one quad per shape instead of a triangle fan. Needs a current
// GL 3.3 context for its whole life (construction, drawing, destruction). Blending is
// premultiplied alpha; the viewport is the frame's top-down pixel space.
#include <cstddef>
#include <span>
#include <vector>

#include "render/frame_scene.hpp"

namespace swarmagg {

class InstancedShapes {
 public:
  InstancedShapes();  // compiles the shaders; throws std::runtime_error on GL errors
  ~InstancedShapes();
  InstancedShapes(const InstancedShapes&) = delete;
  InstancedShapes& operator=(const InstancedShapes&) = delete;

  enum class Layer { Tints, Rings, Links, Bodies, Marks, Walls };
  static constexpr int kLayerCount = 6;

  void set_viewport(int width, int height);
  void draw(Layer layer, std::span<const CircleInstance> circles);
  void draw(Layer layer, std::span<const SegmentInstance> segments);

 private:
  struct Batch {
    unsigned vao = 0;
    unsigned vbo = 0;
  };
  void upload(Batch& batch, const void* data, std::size_t bytes);

  unsigned corner_vbo_ = 0;
  unsigned circle_program_ = 0;
  unsigned segment_program_ = 0;
  int circle_viewport_ = -1;  // uniform locations
  int segment_viewport_ = -1;
  Batch batches_[kLayerCount];
};

}  // namespace swarmagg
