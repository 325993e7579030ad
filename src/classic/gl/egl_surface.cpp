#include "egl_surface.h"

#include <cstdio>
#include <cstring>
#include <exception>

#include "platform/egl_context.h"

namespace ffc::classic {

namespace {

class EglSurface final : public MesaSurface {
 public:
  explicit EglSurface(const platform::EglRequest& r) : context_(r) {}
  bool make_current() override {
    try {
      context_.make_current();
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }
  void release() override { platform::EglContext::release(); }
  void resize(int width, int height) override { context_.resize(width, height); }
  void fill(Table& table) const override {
    for (int i = 0; i < kEntryCount; ++i) table.fn[i] = platform::EglContext::proc_address(kEntryNames[i]);
  }
  // Read by a context of its own: the program's pixel-store state plays no part (egl_context.h).
  void read_rgba(unsigned char* out) override {
    try {
      context_.read_rgba(out);
    } catch (const std::exception& e) {  // a C caller: report, and hand back a black picture
      std::fprintf(stderr, "ffcompat: cannot read the mesa (egl) surface: %s\n", e.what());
      std::memset(out, 0, size_t(context_.width()) * context_.height() * 4);
    }
  }

 private:
  platform::EglContext context_;  // finishes its drawing before it goes
};

}  // namespace

std::unique_ptr<MesaSurface> make_egl_surface(int width, int height, std::string& why) {
  try {
    platform::EglRequest r;  // compatibility profile: the fixed-function pipeline is the point
    r.width = width, r.height = height;
    return std::make_unique<EglSurface>(r);
  } catch (const std::exception& e) {
    why = e.what();
    return nullptr;
  }
}

}  // namespace ffc::classic
