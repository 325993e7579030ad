// The OSMesa platform: Mesa renders into a buffer of ours in memory.
#include <GL/osmesa.h>

#include <cstring>
#include <mutex>
#include <stdexcept>
#include <unordered_set>
#include <vector>

#include "backends/mesa/mesa_platform.h"

namespace ffc::backends::mesa {

namespace {

// The OSMesa contexts alive in this process. OSMesaGetCurrentContext answers from Mesa's record of
// the current context, which EGL's contexts share: after an EGL context was made current it
// returns that one, which is no OSMesa context. Only a context found here is made current again.
std::mutex live_mutex;
std::unordered_set<OSMesaContext>& live() {
  static std::unordered_set<OSMesaContext> contexts;
  return contexts;
}

bool is_live(OSMesaContext ctx) {
  std::lock_guard<std::mutex> lock(live_mutex);
  return live().count(ctx) != 0;
}

// Destroys a context after finishing its queued drawing. Mesa 22.3 frees a context's buffers
// while llvmpipe may still hold immediate-mode vertices for them unflushed: destroying it then
// (from a later begin() or the destructor) crashes inside OSMesaDestroyContext. glFinish with the
// context current drains that queue first. The context that was current before (another
// backend's, possibly) is made current again afterwards, with its own buffer.
void finish_and_destroy(OSMesaContext ctx, std::vector<uint8_t>& buffer, int width, int height) {
  const OSMesaContext previous = OSMesaGetCurrentContext();
  GLint pw = 0, ph = 0, pformat = 0;
  void* pbuffer = nullptr;
  const bool restore = previous && previous != ctx && is_live(previous) &&
                       OSMesaGetColorBuffer(previous, &pw, &ph, &pformat, &pbuffer);
  if (OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    // Straight from OSMesa, not through our dispatch: it may point at another backend now.
    using Finish = void (*)();
    if (auto finish = reinterpret_cast<Finish>(OSMesaGetProcAddress("glFinish"))) finish();
  }
  {
    std::lock_guard<std::mutex> lock(live_mutex);
    live().erase(ctx);
  }
  OSMesaDestroyContext(ctx);
  if (restore) OSMesaMakeCurrent(previous, pbuffer, GL_UNSIGNED_BYTE, pw, ph);
}

class OsMesaPlatform final : public Platform {
 public:
  OsMesaPlatform(int width, int height) : width_(width), height_(height), buffer_(size_t(width) * height * 4, 0) {
    const int attribs[] = {OSMESA_FORMAT,       OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                           OSMESA_PROFILE,      OSMESA_COMPAT_PROFILE,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context_) throw std::runtime_error("mesa (osmesa): OSMesaCreateContextAttribs failed");
    {
      std::lock_guard<std::mutex> lock(live_mutex);
      live().insert(context_);
    }
    make_current();
  }
  ~OsMesaPlatform() override { finish_and_destroy(context_, buffer_, width_, height_); }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
      throw std::runtime_error("mesa (osmesa): OSMesaMakeCurrent failed");
  }

  void read(image::Image& img) override {
    if (auto finish = reinterpret_cast<void (*)()>(OSMesaGetProcAddress("glFinish"))) finish();
    img.width = width_, img.height = height_;
    img.rgba.resize(size_t(width_) * height_ * 4);
    const size_t row = size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)  // OSMesa's rows are bottom-up
      std::memcpy(&img.rgba[size_t(y) * row], &buffer_[size_t(height_ - 1 - y) * row], row);
  }

 private:
  OSMesaContext context_ = nullptr;
  int width_, height_;
  std::vector<uint8_t> buffer_;  // OSMesa renders here, bottom row first
};

}  // namespace

std::unique_ptr<Platform> make_osmesa(int width, int height) { return std::make_unique<OsMesaPlatform>(width, height); }

void* osmesa_proc_address(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

}  // namespace ffc::backends::mesa
