// ffcompat_surface.h: a drawing surface on soft (ours, through backends::make), glsl (our state
// tracker drawing through a core-profile EGL context, also through backends::make) or mesa (OSMesa
// or EGL, mesa_surface.h), each with its table of entry points for the exports.
#include "ffcompat_surface.h"

#include <GL/gl.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>

#include "backends/backend.h"
#include "image/image.h"
#include "mesa_surface.h"
#include "raster/raster.h"
#include "state/context.h"
#include "state/soft_gl.h"
#include "table.h"
#ifdef FFCOMPAT_CLASSIC_GLSL
#include "backends/glsl/glsl_backend.h"
#include "platform/egl_context.h"
#endif

struct ffcompat_surface {
  std::string backend;
  int width = 0, height = 0;
  ffc::classic::Table table;
  std::unique_ptr<ffc::backends::Backend> soft;  // one of these two (glsl's is a soft one: our state)
  std::unique_ptr<ffc::classic::MesaSurface> mesa;
#ifdef FFCOMPAT_CLASSIC_GLSL
  ffc::backends::GlslBackend* glsl = nullptr;  // `soft`, when it is the GLSL backend
#endif
  std::string platform;  // mesa's: "osmesa" or "egl"
};

namespace {

using ffc::classic::Table;

// The surface current on this thread, for ffcompat_surface_make_current(nullptr) to release.
thread_local ffcompat_surface* g_surface = nullptr;

// Every soft variant answers the same names: those of state::proc_address.
const Table& soft_table() {
  static const Table t = [] {
    Table s;
    for (int i = 0; i < ffc::classic::kEntryCount; ++i) s.fn[i] = ffc::state::proc_address(ffc::classic::kEntryNames[i]);
    s.soft = true;
    return s;
  }();
  return t;
}

std::string valid_names() {
  std::string out;
  bool mesa = false;
  for (const std::string& n : ffc::backends::names()) {
    out += (out.empty() ? "" : ", ") + n;
    mesa = mesa || n == "mesa";
  }
  return mesa ? out : out + ", mesa";
}

#ifdef FFCOMPAT_CLASSIC_GLSL
// glsl surfaces alive. OSMesa and EGL share Mesa's dispatch (libglapi): with a glsl surface's EGL
// context bound there, OSMesa takes that context for its own current one when it finishes or reads
// a mesa surface and puts it back after (osmesa.cpp), reading OSMesa's fields out of an EGL context
// (measured: "OSMesaMakeCurrent(unsupported format/type)"). Such work on a mesa surface is done
// with EGL released, the current surface bound again after.
std::atomic<int> g_glsl_surfaces{0};
struct EglQuiet {
  bool on;
  explicit EglQuiet(const ffcompat_surface* s) : on(s->mesa && g_glsl_surfaces.load() > 0) {
    if (on) ffc::platform::EglContext::release();
  }
  ~EglQuiet() {
    if (on && g_surface) ffcompat_surface_make_current(g_surface);
  }
};
#else
struct EglQuiet {
  explicit EglQuiet(const ffcompat_surface*) {}
};
#endif

bool valid_size(int width, int height) { return width > 0 && height > 0 && width <= 16384 && height <= 16384; }

bool is_soft(const std::string& name) {
  for (const std::string& n : ffc::backends::names())
    if (n == name && n != "mesa") return true;
  return false;
}

}  // namespace

extern "C" {

ffcompat_surface* ffcompat_surface_create(int width, int height) {
  const char* env = std::getenv("FFCOMPAT_BACKEND");
  const std::string name = env && *env ? env : "soft";
  if (name != "mesa" && !is_soft(name)) {
    std::fprintf(stderr, "ffcompat: unknown backend '%s' in FFCOMPAT_BACKEND (valid: %s)\n", name.c_str(),
                 valid_names().c_str());
    return nullptr;
  }
  if (!valid_size(width, height)) {
    std::fprintf(stderr, "ffcompat: surface size %dx%d is outside 1..16384\n", width, height);
    return nullptr;
  }
  std::unique_ptr<ffcompat_surface> s(new ffcompat_surface);
  s->backend = name;
  s->width = width, s->height = height;
  try {
    if (name == "mesa") {
      std::string why;
      s->mesa = ffc::classic::make_mesa_surface(width, height, s->platform, why);
      if (!s->mesa) {
        std::fprintf(stderr, "ffcompat: the mesa backend is unavailable%s: %s\n",
                     s->platform.empty() ? "" : (" on " + s->platform).c_str(), why.c_str());
        return nullptr;
      }
      s->mesa->fill(s->table);
    } else {
      // glsl keeps our state::Context as soft does (the same entry points); only its draws go to
      // an EGL core-profile context.
      s->soft = ffc::backends::make(name);
      s->soft->begin(width, height);
      s->table = soft_table();
#ifdef FFCOMPAT_CLASSIC_GLSL
      s->glsl = dynamic_cast<ffc::backends::GlslBackend*>(s->soft.get());
      if (s->glsl) g_glsl_surfaces.fetch_add(1);
#endif
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ffcompat: cannot make a %s surface: %s\n", name.c_str(), e.what());
    return nullptr;
  }
  s->table.backend = s->backend.c_str();
  ffc::classic::g_current = &s->table;
  g_surface = s.get();
  return s.release();
}

void ffcompat_surface_make_current(ffcompat_surface* s) {
  if (!s) {
    // EGL keeps a context current until told otherwise, and a window's own EGL context (our
    // GLUT's GLFW window) is about to be made current: ours is released first.
    if (g_surface && g_surface->mesa) g_surface->mesa->release();
#ifdef FFCOMPAT_CLASSIC_GLSL
    if (g_surface && g_surface->glsl) ffc::platform::EglContext::release();
#endif
    ffc::classic::g_current = nullptr;
    g_surface = nullptr;
    return;
  }
  try {
    if (s->mesa ? s->mesa->make_current() : (s->soft->resume(), true)) {
      ffc::classic::g_current = &s->table;
      g_surface = s;
      return;
    }
    std::fprintf(stderr, "ffcompat: cannot make the %s surface current\n", s->backend.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ffcompat: cannot make the %s surface current: %s\n", s->backend.c_str(), e.what());
  }
}

void ffcompat_surface_read_rgba(ffcompat_surface* s, unsigned char* out) {
  if (!s || !out) return;
  if (s->mesa) {
    const EglQuiet quiet(s);
    return s->mesa->read_rgba(out);
  }
#ifdef FFCOMPAT_CLASSIC_GLSL
  // A glsl surface read while another is current: EGL may still count this context as current
  // after OSMesa took Mesa's dispatch (GlslBackend::bind), so it is released and bound for the
  // read, and the current surface gets its context back.
  if (s->glsl && g_surface != s) ffc::platform::EglContext::release();
#endif
  ffc::image::Image img;
  s->soft->read_into(img);
  std::memcpy(out, img.rgba.data(), img.rgba.size());
#ifdef FFCOMPAT_CLASSIC_GLSL
  if (s->glsl && g_surface && g_surface != s) ffcompat_surface_make_current(g_surface);
#endif
}

int ffcompat_surface_resize(ffcompat_surface* s, int width, int height) {
  if (!s || !valid_size(width, height)) return -1;
  if (s->mesa) {
    try {
      const EglQuiet quiet(s);
      s->mesa->resize(width, height);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ffcompat: cannot resize the %s surface: %s\n", s->backend.c_str(), e.what());
      return -1;
    }
#ifdef FFCOMPAT_CLASSIC_GLSL
  } else if (s->glsl) {
    // Resizing binds the surface's EGL context; the current surface, another, gets its own back.
    try {
      s->glsl->resize(width, height);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ffcompat: cannot resize the %s surface: %s\n", s->backend.c_str(), e.what());
      return -1;
    }
    if (g_surface && g_surface != s) ffcompat_surface_make_current(g_surface);
#endif
  } else {
    // The soft context is reached by making it current (the backend keeps it to itself); the
    // context that was current before comes back after. A new Framebuffer is all a size is: the
    // rasterizer reads the size from it at every draw.
    ffc::state::Context* const previous = ffc::state::Context::current();
    try {
      s->soft->resume();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ffcompat: cannot resize the %s surface: %s\n", s->backend.c_str(), e.what());
      return -1;
    }
    ffc::state::Context::current()->framebuffer() = ffc::raster::Framebuffer(width, height);
    ffc::state::Context::make_current(previous);
  }
  s->width = width, s->height = height;
  return 0;
}

int ffcompat_surface_width(const ffcompat_surface* s) { return s ? s->width : 0; }
int ffcompat_surface_height(const ffcompat_surface* s) { return s ? s->height : 0; }
const char* ffcompat_surface_backend(const ffcompat_surface* s) { return s ? s->backend.c_str() : ""; }

void ffcompat_surface_destroy(ffcompat_surface* s) {
  if (!s) return;
  if (ffc::classic::g_current == &s->table) ffc::classic::g_current = nullptr;
  if (g_surface == s) g_surface = nullptr;
#ifdef FFCOMPAT_CLASSIC_GLSL
  if (s->glsl) g_glsl_surfaces.fetch_sub(1);
#endif
  {
    const EglQuiet quiet(s);
    delete s;  // a glsl or EGL surface binds its own context to free its objects: the current one's comes back
  }
  if (g_surface) ffcompat_surface_make_current(g_surface);
}

void* ffcompat_get_proc_address(const char* name) { return ffc::classic::export_address(name); }

// The loader classic programs reach for extensions with (GLX's, declared in <GL/glx.h>): the same
// answer, so a function of gl.h loaded by name still goes to the current surface, and anything
// else is null rather than a symbol the program cannot find at startup.
using GlxProc = void (*)();
GlxProc glXGetProcAddressARB(const GLubyte* name) {
  return reinterpret_cast<GlxProc>(ffc::classic::export_address(reinterpret_cast<const char*>(name)));
}
GlxProc glXGetProcAddress(const GLubyte* name) { return glXGetProcAddressARB(name); }

}  // extern "C"
