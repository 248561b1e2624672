#pragma once
// An off-screen OpenGL 3.3 core context (OSMesa, llvmpipe) that renders into a caller's
// pixel buffer: no display, no window system, DISPLAY may be unset. One thread at a time may
// use it: bind() before GL calls, release() after, so a context can move between threads.
// The buffer receives the frame at glFinish(), GL window row 0 first (OSMesa's "y up"); the
// renderer maps its top-down pixel rows onto window rows one to one, so it reads top-down.
#include <cstdint>
#include <span>

namespace swarmagg {

class OsMesaContext {
 public:
  OsMesaContext(int width, int height);  // throws std::runtime_error if OSMesa fails
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  // `target` must hold width * height * 4 bytes (RGBA8) and outlive the binding.
  void bind(std::span<std::uint8_t> target);
  void release();
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void* context_ = nullptr;  // OSMesaContext
  int width_;
  int height_;
};

}  // namespace swarmagg
