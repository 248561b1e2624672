#include "render/osmesa_context.hpp"

#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace swarmagg {

OsMesaContext::OsMesaContext(int width, int height) : width_(width), height_(height) {
  // No depth, stencil or accumulation buffers: frames are layered back to front.
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    throw std::runtime_error(
        "cannot create an off-screen OpenGL 3.3 context (OSMesa); is libosmesa6 installed?");
  }
}

OsMesaContext::~OsMesaContext() {
  if (OSMesaGetCurrentContext() == static_cast<OSMesaContext>(context_)) release();
  OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void OsMesaContext::bind(std::span<std::uint8_t> target) {
  if (target.size() != static_cast<std::size_t>(width_) * height_ * 4) {
    throw std::invalid_argument("OSMesa target buffer of " + std::to_string(target.size()) +
                                " bytes for " + std::to_string(width_) + "x" +
                                std::to_string(height_));
  }
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), target.data(), GL_UNSIGNED_BYTE,
                         width_, height_)) {
    throw std::runtime_error("cannot bind the OSMesa context to a " + std::to_string(width_) + "x" +
                             std::to_string(height_) + " buffer");
  }
}

void OsMesaContext::release() {
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
}

}  // namespace swarmagg
