#pragma once
// An off-screen OpenGL 3.3 core context (OSMesa, llvmpipe) that renders into a pixel buffer
// it owns: no display, no window system, DISPLAY may be unset. One thread at a time may use
// it: bind() before GL calls, release() after, so a context can move between threads.
// OSMesa writes rows bottom-up (GL window row 0 first); FrameRenderer draws upside down so
// the buffer reads top-down.
#include <cstdint>
#include <span>
#include <vector>

namespace swarmagg {

class OsMesaContext {
 public:
  OsMesaContext(int width, int height);  // throws std::runtime_error if OSMesa fails
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void bind();
  void release();
  int width() const { return width_; }
  int height() const { return height_; }
  // RGBA8 rows, GL window row 0 first; complete after glFinish().
  std::span<std::uint8_t> pixels() { return pixels_; }

 private:
  void* context_ = nullptr;  // OSMesaContext
  int width_;
  int height_;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace swarmagg
