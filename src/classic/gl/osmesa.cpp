#include "osmesa.h"

#include <dlfcn.h>

#include <cstring>
#include <functional>

// Built only where ffcompat is built with OSMesa (FFCOMPAT_WITH_OSMESA): libOSMesa itself is
// found at run time.
#include <GL/osmesa.h>

namespace ffc::classic {

namespace {

// The few OSMesa functions used, found once in the privately loaded library.
struct OsMesa {
  decltype(&::OSMesaCreateContextAttribs) create = nullptr;
  decltype(&::OSMesaMakeCurrent) make_current = nullptr;
  decltype(&::OSMesaDestroyContext) destroy = nullptr;
  decltype(&::OSMesaGetCurrentContext) current = nullptr;
  decltype(&::OSMesaGetColorBuffer) color_buffer = nullptr;
  decltype(&::OSMesaGetProcAddress) proc = nullptr;
  std::string error;  // why it could not be loaded
};

const OsMesa& osmesa() {
  static const OsMesa loaded = [] {
    OsMesa m;
    // Never closed: Mesa's threads and atexit handlers outlive any surface.
    void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND);
    if (!lib) {
      const char* e = dlerror();
      m.error = std::string("cannot load libOSMesa.so.8 (Debian: libosmesa6): ") + (e ? e : "unknown error");
      return m;
    }
    bool ok = true;
    auto find = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(lib, name));
      ok = ok && fn;
    };
    find(m.create, "OSMesaCreateContextAttribs");
    find(m.make_current, "OSMesaMakeCurrent");
    find(m.destroy, "OSMesaDestroyContext");
    find(m.current, "OSMesaGetCurrentContext");
    find(m.color_buffer, "OSMesaGetColorBuffer");
    find(m.proc, "OSMesaGetProcAddress");
    if (!ok) m.error = "libOSMesa.so.8 lacks one of the OSMesa functions used";
    return m;
  }();
  return loaded;
}

using GlFinish = void (*)();

// Runs `f` with `ctx` current on OSMesa, then makes the context that was current before current
// again, with its own buffer (it may belong to another surface).
void with_current(OSMesaContext ctx, std::vector<uint8_t>& buffer, int width, int height,
                  const std::function<void()>& f) {
  const OsMesa& m = osmesa();
  const OSMesaContext previous = m.current();
  GLint pw = 0, ph = 0, pformat = 0;
  void* pbuffer = nullptr;
  const bool restore = previous && previous != ctx && m.color_buffer(previous, &pw, &ph, &pformat, &pbuffer);
  if (m.make_current(ctx, buffer.data(), GL_UNSIGNED_BYTE, width, height)) f();
  if (restore) m.make_current(previous, pbuffer, GL_UNSIGNED_BYTE, pw, ph);
}

void finish() {
  if (auto fn = reinterpret_cast<GlFinish>(osmesa().proc("glFinish"))) fn();
}

}  // namespace

std::unique_ptr<MesaSurface> OsMesaSurface::make(int width, int height, std::string& why) {
  const OsMesa& m = osmesa();
  if (!m.error.empty()) {
    why = m.error;
    return nullptr;
  }
  // A compatibility context: the fixed-function pipeline is the point.
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                         OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
  std::unique_ptr<OsMesaSurface> s(new OsMesaSurface);
  s->context_ = m.create(attribs, nullptr);
  if (!s->context_) {
    why = "OSMesaCreateContextAttribs failed";
    return nullptr;
  }
  s->width_ = width, s->height_ = height;
  s->buffer_.assign(size_t(width) * height * 4, 0);
  if (!s->make_current()) {
    why = "OSMesaMakeCurrent failed";
    return nullptr;
  }
  return s;
}

// Mesa 22.3 frees a context's buffers while llvmpipe may still hold immediate-mode vertices for
// them unflushed, and destroying it then crashes inside OSMesaDestroyContext: the context is
// finished, current, first.
OsMesaSurface::~OsMesaSurface() {
  if (!context_) return;
  auto ctx = static_cast<OSMesaContext>(context_);
  with_current(ctx, buffer_, width_, height_, finish);
  osmesa().destroy(ctx);
}

bool OsMesaSurface::make_current() {
  return osmesa().make_current(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE, width_,
                               height_);
}

void OsMesaSurface::resize(int width, int height) {
  auto ctx = static_cast<OSMesaContext>(context_);
  with_current(ctx, buffer_, width_, height_, finish);
  buffer_.assign(size_t(width) * height * 4, 0);
  width_ = width, height_ = height;
  if (osmesa().current() == ctx) make_current();
}

void OsMesaSurface::fill(Table& table) const {
  for (int i = 0; i < kEntryCount; ++i) table.fn[i] = reinterpret_cast<void*>(osmesa().proc(kEntryNames[i]));
}

void OsMesaSurface::read_rgba(unsigned char* out) {
  with_current(static_cast<OSMesaContext>(context_), buffer_, width_, height_, finish);
  const size_t row = size_t(width_) * 4;
  for (int y = 0; y < height_; ++y)  // OSMesa's rows are bottom-up
    std::memcpy(out + size_t(y) * row, &buffer_[size_t(height_ - 1 - y) * row], row);
}

}  // namespace ffc::classic
