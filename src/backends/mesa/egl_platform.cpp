// The EGL platform: a compatibility context on a pbuffer (platform::EglContext).
#include <stdexcept>

#include "backends/mesa/mesa_platform.h"
#include "platform/egl_context.h"

namespace ffc::backends::mesa {

namespace {

class EglPlatform final : public Platform {
 public:
  EglPlatform(int width, int height) : context_(request(width, height)) {}

  void make_current() override { context_.make_current(); }

  void read(image::Image& img) override {
    img.width = context_.width(), img.height = context_.height();
    img.rgba.resize(size_t(img.width) * img.height * 4);
    context_.read_rgba(img.rgba.data());
  }

 private:
  static platform::EglRequest request(int width, int height) {
    platform::EglRequest r;  // compatibility profile, GL 2.1 at least: Mesa gives its highest
    r.width = width, r.height = height;
    return r;
  }
  platform::EglContext context_;  // finishes its drawing before it goes (egl_context.cpp)
};

}  // namespace

std::unique_ptr<Platform> make_egl(int width, int height) { return std::make_unique<EglPlatform>(width, height); }

void* egl_proc_address(const char* name) { return platform::EglContext::proc_address(name); }

}  // namespace ffc::backends::mesa
