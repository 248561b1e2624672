#include "render/instanced_shapes.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace swarmagg {
namespace {

static_assert(sizeof(CircleInstance) == 24 && offsetof(CircleInstance, fill) == 16 &&
              offsetof(CircleInstance, stroke) == 20);
static_assert(sizeof(SegmentInstance) == 24 && offsetof(SegmentInstance, half_width) == 16 &&
              offsetof(SegmentInstance, colour) == 20);

// Pixel space (top-down rows) maps to GL window rows directly; OSMesa stores window row 0
// first, so the buffer comes out top-down.
constexpr const char* kCircleVertex = R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 geometry;  // centre x, y, outer radius, stroke width (pixels)
layout(location = 2) in vec4 fill;
layout(location = 3) in vec4 stroke;
uniform vec2 viewport;
out vec2 local;
flat out vec2 shape;
flat out vec4 fill_colour;
flat out vec4 stroke_colour;
void main() {
  float reach = geometry.z + 0.5;  // coverage is zero from R + 0.5 on
  local = corner * reach;
  shape = geometry.zw;
  fill_colour = vec4(fill.rgb * fill.a, fill.a);
  stroke_colour = vec4(stroke.rgb * stroke.a, stroke.a);
  gl_Position = vec4((geometry.xy + local) / viewport * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kCircleFragment = R"(#version 330 core
in vec2 local;
flat in vec2 shape;
flat in vec4 fill_colour;
flat in vec4 stroke_colour;
out vec4 colour;
void main() {
  float d = length(local);
  float cover = clamp(shape.x - d + 0.5, 0.0, 1.0);
  float inside = clamp(shape.x - shape.y - d + 0.5, 0.0, 1.0);
  // Nothing outside the shape, nothing inside a ring (fill alpha 0).
  if (cover <= 0.0 || (inside >= 1.0 && fill_colour.a <= 0.0)) discard;
  colour = mix(stroke_colour, fill_colour, inside) * cover;
}
)";

constexpr const char* kSegmentVertex = R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 ends;  // x0, y0, x1, y1 (pixels)
layout(location = 2) in float half_width;
layout(location = 3) in vec4 colour_in;
uniform vec2 viewport;
out vec2 local;
flat out vec2 shape;
flat out vec4 colour_out;
void main() {
  vec2 axis = ends.zw - ends.xy;
  float len = length(axis);
  vec2 dir = len > 0.0 ? axis / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  float reach = half_width + 0.5;
  shape = vec2(0.5 * len, half_width);
  local = vec2(corner.x * (shape.x + reach), corner.y * reach);
  vec2 p = 0.5 * (ends.xy + ends.zw) + dir * local.x + normal * local.y;
  colour_out = vec4(colour_in.rgb * colour_in.a, colour_in.a);
  gl_Position = vec4(p / viewport * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kSegmentFragment = R"(#version 330 core
in vec2 local;
flat in vec2 shape;
flat in vec4 colour_out;
out vec4 colour;
void main() {
  vec2 q = vec2(max(abs(local.x) - shape.x, 0.0), local.y);
  float cover = clamp(shape.y - length(q) + 0.5, 0.0, 1.0);
  if (cover <= 0.0) discard;
  colour = colour_out * cover;
}
)";

GLuint compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("render: shader does not compile: ") + log);
  }
  return shader;
}

GLuint link(const char* vertex, const char* fragment) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error(std::string("render: shaders do not link: ") + log);
  }
  return program;
}

const void* byte_offset(std::size_t offset) {
  return reinterpret_cast<const void*>(offset);
}

bool is_circle_layer(InstancedShapes::Layer layer) {
  return layer == InstancedShapes::Layer::Tints || layer == InstancedShapes::Layer::Rings ||
         layer == InstancedShapes::Layer::Bodies || layer == InstancedShapes::Layer::Marks;
}

}  // namespace

InstancedShapes::InstancedShapes() {
  circle_program_ = link(kCircleVertex, kCircleFragment);
  segment_program_ = link(kSegmentVertex, kSegmentFragment);
  circle_viewport_ = glGetUniformLocation(circle_program_, "viewport");
  segment_viewport_ = glGetUniformLocation(segment_program_, "viewport");

  const float corners[] = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f};
  glGenBuffers(1, &corner_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, corner_vbo_);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);

  for (int l = 0; l < kLayerCount; ++l) {
    Batch& batch = batches_[l];
    glGenVertexArrays(1, &batch.vao);
    glGenBuffers(1, &batch.vbo);
    glBindVertexArray(batch.vao);
    glBindBuffer(GL_ARRAY_BUFFER, corner_vbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, byte_offset(0));
    glBindBuffer(GL_ARRAY_BUFFER, batch.vbo);
    for (GLuint a = 1; a <= 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribDivisor(a, 1);
    }
    if (is_circle_layer(static_cast<Layer>(l))) {
      const GLsizei stride = sizeof(CircleInstance);
      glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, byte_offset(0));
      glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                            byte_offset(offsetof(CircleInstance, fill)));
      glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                            byte_offset(offsetof(CircleInstance, stroke)));
    } else {
      const GLsizei stride = sizeof(SegmentInstance);
      glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, byte_offset(0));
      glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                            byte_offset(offsetof(SegmentInstance, half_width)));
      glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                            byte_offset(offsetof(SegmentInstance, colour)));
    }
  }
  glBindVertexArray(0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied alpha
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    throw std::runtime_error("render: OpenGL error " + std::to_string(error) +
                             " while setting up shaders");
  }
}

InstancedShapes::~InstancedShapes() {
  for (Batch& batch : batches_) {
    glDeleteVertexArrays(1, &batch.vao);
    glDeleteBuffers(1, &batch.vbo);
  }
  glDeleteBuffers(1, &corner_vbo_);
  glDeleteProgram(circle_program_);
  glDeleteProgram(segment_program_);
}

void InstancedShapes::set_viewport(int width, int height) {
  glViewport(0, 0, width, height);
  glUseProgram(circle_program_);
  glUniform2f(circle_viewport_, static_cast<float>(width), static_cast<float>(height));
  glUseProgram(segment_program_);
  glUniform2f(segment_viewport_, static_cast<float>(width), static_cast<float>(height));
}

void InstancedShapes::upload(Batch& batch, const void* data, std::size_t bytes) {
  glBindBuffer(GL_ARRAY_BUFFER, batch.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STREAM_DRAW);
  glBindVertexArray(batch.vao);
}

void InstancedShapes::draw(Layer layer, std::span<const CircleInstance> circles) {
  if (circles.empty()) return;
  if (!is_circle_layer(layer)) throw std::logic_error("render: circles drawn on a line layer");
  upload(batches_[static_cast<int>(layer)], circles.data(), circles.size_bytes());
  glUseProgram(circle_program_);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(circles.size()));
}

void InstancedShapes::draw(Layer layer, std::span<const SegmentInstance> segments) {
  if (segments.empty()) return;
  if (is_circle_layer(layer)) throw std::logic_error("render: segments drawn on a circle layer");
  upload(batches_[static_cast<int>(layer)], segments.data(), segments.size_bytes());
  glUseProgram(segment_program_);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(segments.size()));
}

}  // namespace swarmagg
