#include "backends/mesa/mesa_backend.h"

#include <GL/osmesa.h>

#include <cstring>
#include <stdexcept>

#include "gl/dispatch.h"

namespace ffc::backends {

namespace {

// Destroys a context after finishing its queued drawing. Mesa 22.3 frees a context's buffers
// while llvmpipe may still hold immediate-mode vertices for them unflushed: destroying it then
// (from a later begin() or the destructor) crashes inside OSMesaDestroyContext. glFinish with the
// context current drains that queue first. The context that was current before (another
// backend's, possibly) is made current again afterwards, with its own buffer.
void finish_and_destroy(OSMesaContext ctx, std::vector<uint8_t>& buffer, int width, int height) {
  const OSMesaContext previous = OSMesaGetCurrentContext();
  GLint pw = 0, ph = 0, pformat = 0;
  void* pbuffer = nullptr;
  const bool restore = previous && previous != ctx && OSMesaGetColorBuffer(previous, &pw, &ph, &pformat, &pbuffer);
  if (OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    // Straight from OSMesa, not through our dispatch: it may point at another backend now.
    using Finish = void (*)();
    if (auto finish = reinterpret_cast<Finish>(OSMesaGetProcAddress("glFinish"))) finish();
  }
  OSMesaDestroyContext(ctx);
  if (restore) OSMesaMakeCurrent(previous, pbuffer, GL_UNSIGNED_BYTE, pw, ph);
}

}  // namespace

MesaBackend::~MesaBackend() {
  if (context_) finish_and_destroy(static_cast<OSMesaContext>(context_), buffer_, width_, height_);
}

static void* osmesa_loader(const char* name) {
  return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

void MesaBackend::begin(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::runtime_error("mesa: framebuffer size " + std::to_string(width) + "x" +
                             std::to_string(height) + " is outside 1..16384");
  // A fresh context per begin(): every picture starts from GL's default state.
  if (context_) finish_and_destroy(static_cast<OSMesaContext>(context_), buffer_, width_, height_);
  context_ = nullptr;
  {
    // A compatibility context: the fixed-function pipeline is what we compare against.
    const int attribs[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,    24,
                           OSMESA_STENCIL_BITS,  0,
                           OSMESA_PROFILE,       OSMESA_COMPAT_PROFILE,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context_) throw std::runtime_error("mesa: OSMesaCreateContextAttribs failed");
  }
  width_ = width;
  height_ = height;
  buffer_.assign(size_t(width) * height * 4, 0);
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE, width, height))
    throw std::runtime_error("mesa: OSMesaMakeCurrent failed");
  const auto missing = gl::load(osmesa_loader);
  if (!missing.empty()) throw std::runtime_error("mesa: OSMesa does not provide " + missing.front());
  glViewport(0, 0, width, height);
}

void MesaBackend::resume() {
  if (!context_) throw std::logic_error("mesa: resume() before begin()");
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw std::runtime_error("mesa: OSMesaMakeCurrent failed");
  gl::load(osmesa_loader);
}

void MesaBackend::read_into(image::Image& img) {
  glFinish();
  img.width = width_, img.height = height_;
  img.rgba.resize(size_t(width_) * height_ * 4);
  const size_t row = size_t(width_) * 4;
  for (int y = 0; y < height_; ++y)  // OSMesa's rows are bottom-up
    std::memcpy(&img.rgba[size_t(y) * row], &buffer_[size_t(height_ - 1 - y) * row], row);
}

}  // namespace ffc::backends

// Offers "mesa" to backends::make(). ffcompat_mesa's users link with -u naming this symbol (its
// INTERFACE_LINK_OPTIONS, and ffcompat.pc), so the linker keeps this object out of the static
// library, and its registration with it.
extern "C" const bool ffcompat_mesa_backend_registered;
const bool ffcompat_mesa_backend_registered = ffc::backends::register_backend(
    "mesa", []() -> std::unique_ptr<ffc::backends::Backend> { return std::make_unique<ffc::backends::MesaBackend>(); });
