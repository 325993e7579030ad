#include "platform/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "platform/egl_api.h"

namespace ffc::platform {

namespace {

const EglApi& egl() { return egl_api(); }

std::string egl_error(const char* what) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", unsigned(egl().GetError()));
  return std::string("egl: ") + what + " failed (EGL error " + hex + ")";
}

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// One display for the process, opened on first use and never terminated: eglTerminate would
// end every context on it at once, and the contexts come and go independently. Its one config
// serves every context and pbuffer, so any context can be made current on any pbuffer (the
// reader below relies on it).
struct Display {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  // Contexts are made without a config where the display allows (EGL_KHR_no_config_context): Mesa
  // then takes the default draw and read buffers from the surface first bound, GL_FRONT for a
  // single-buffered pbuffer, as OSMesa's; a context made with a config says GL_BACK.
  EGLConfig context_config = nullptr;
  std::string platform, why;
};

Display open_display() {
  Display d;
  if (!egl().error.empty()) {
    d.why = egl().error;
    return d;
  }
  const char* client = egl().QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(egl().GetProcAddress("eglGetPlatformDisplayEXT"));
  // The device platform: Mesa's software device (llvmpipe) first, the pictures this project
  // compares against; another device (a GPU's) only when there is no software one.
  if (get_platform_display && has_extension(client, "EGL_EXT_platform_device")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl().GetProcAddress("eglQueryDevicesEXT"));
    auto query_device_string =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(egl().GetProcAddress("eglQueryDeviceStringEXT"));
    EGLint count = 0;
    if (query_devices && query_devices(0, nullptr, &count) && count > 0) {
      std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
      query_devices(count, devices.data(), &count);
      EGLDeviceEXT chosen = devices[0];
      for (EGLDeviceEXT dev : devices) {
        const char* ext = query_device_string ? query_device_string(dev, EGL_EXTENSIONS) : nullptr;
        if (has_extension(ext, "EGL_MESA_device_software")) { chosen = dev; break; }
      }
      d.display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, chosen, nullptr);
      d.platform = "device";
    }
  }
  if (d.display != EGL_NO_DISPLAY && !egl().Initialize(d.display, nullptr, nullptr)) d.display = EGL_NO_DISPLAY;
  if (d.display == EGL_NO_DISPLAY && get_platform_display && has_extension(client, "EGL_MESA_platform_surfaceless")) {
    d.display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    d.platform = "surfaceless";
    if (d.display != EGL_NO_DISPLAY && !egl().Initialize(d.display, nullptr, nullptr)) d.display = EGL_NO_DISPLAY;
  }
  if (d.display == EGL_NO_DISPLAY) {
    d.display = egl().GetDisplay(EGL_DEFAULT_DISPLAY);
    d.platform = "default";
    if (d.display != EGL_NO_DISPLAY && !egl().Initialize(d.display, nullptr, nullptr)) d.display = EGL_NO_DISPLAY;
  }
  if (d.display == EGL_NO_DISPLAY) {
    d.why = egl_error("no headless display (device, surfaceless or default): eglInitialize");
    return d;
  }
  // "OpenGL_ES" alone does not give desktop GL.
  const char* apis = egl().QueryString(d.display, EGL_CLIENT_APIS);
  bool desktop = false;
  for (const char* p = apis; p && (p = std::strstr(p, "OpenGL")); p += 6)
    if (std::strncmp(p, "OpenGL_ES", 9) != 0) desktop = true;
  if (!desktop) {
    d.why = std::string("egl: the ") + d.platform + " display offers no desktop OpenGL (client APIs: " +
            (apis ? apis : "none") + ")";
    d.display = EGL_NO_DISPLAY;
    return d;
  }
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                   EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                   EGL_DEPTH_SIZE, 24, EGL_NONE};
  EGLint configs = 0;
  if (!egl().ChooseConfig(d.display, config_attribs, &d.config, 1, &configs) || configs < 1) {
    d.why = egl_error("eglChooseConfig (RGBA8, depth 24, pbuffer, OpenGL)");
    d.display = EGL_NO_DISPLAY;
    return d;
  }
  const bool no_config = has_extension(egl().QueryString(d.display, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
  d.context_config = no_config ? EGL_NO_CONFIG_KHR : d.config;
  return d;
}

const Display& display() {
  static std::once_flag once;
  static Display d;
  std::call_once(once, [] { d = open_display(); });
  return d;
}

// The OpenGL context current on this thread and its surfaces, to be made current again after a
// context of ours was borrowed.
struct Current {
  EGLDisplay display;
  EGLSurface draw, read;
  EGLContext context;
  EGLenum api;
};

Current save_current() {
  Current c;
  c.api = egl().QueryAPI();
  egl().BindAPI(EGL_OPENGL_API);  // eglGetCurrent* answer for the bound API
  c.display = egl().GetCurrentDisplay();
  c.draw = egl().GetCurrentSurface(EGL_DRAW);
  c.read = egl().GetCurrentSurface(EGL_READ);
  c.context = egl().GetCurrentContext();
  return c;
}

void restore_current(const Current& c, EGLDisplay ours) {
  egl().BindAPI(EGL_OPENGL_API);
  if (c.context == EGL_NO_CONTEXT)
    egl().MakeCurrent(ours, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  else
    egl().MakeCurrent(c.display, c.draw, c.read, c.context);
  egl().BindAPI(c.api);
}

// Makes `context` current on `surface`, really. EGL treats making the current context current
// again as done, but another platform of Mesa in the same process (OSMesa, which shares Mesa's
// record of the current dispatch) may have taken the thread's GL calls since: measured, the calls
// after such a make-current went to the OSMesa context. Releasing first makes Mesa bind again.
EGLBoolean bind(EGLDisplay display, EGLSurface surface, EGLContext context) {
  egl().BindAPI(EGL_OPENGL_API);
  if (egl().GetCurrentContext() == context && egl().GetCurrentSurface(EGL_DRAW) == surface)
    egl().MakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  return egl().MakeCurrent(display, surface, surface, context);
}

template <class F>
F gl(const char* name) {
  return reinterpret_cast<F>(egl().GetProcAddress(name));
}

// Drains llvmpipe's queue of the current context: its buffers must not go (a destroyed context
// or pbuffer) while it still holds drawing for them (as for OSMesa, see the Mesa backend).
void finish_current() {
  if (auto finish = gl<void (*)()>("glFinish")) finish();
}

// The context that reads pbuffers back, one for the display, made on first use; the mutex keeps
// two threads from making it current at once.
std::mutex reader_mutex;
EGLContext reader_context(const Display& d) {
  static EGLContext reader = EGL_NO_CONTEXT;
  if (reader == EGL_NO_CONTEXT) {
    egl().BindAPI(EGL_OPENGL_API);
    const EGLint none[] = {EGL_NONE};  // GL's defaults: any version, compatibility
    reader = egl().CreateContext(d.display, d.context_config, EGL_NO_CONTEXT, none);
    if (reader == EGL_NO_CONTEXT) throw std::runtime_error(egl_error("eglCreateContext (the reader)"));
  }
  return reader;
}

// A new pbuffer, its colour and depth zero. GL leaves a new buffer's contents undefined; llvmpipe's
// buffers under OSMesa start at 0, colour and depth alike, and so do ours (src/raster/raster.h), so
// a program that draws before it clears draws the same everywhere. Cleared by the reader context
// (reader_mutex held by the caller), whose state is its own, so no drawing context's changes.
EGLSurface make_pbuffer(const Display& d, int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::runtime_error("egl: framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is outside 1..16384");
  const EGLint surface_attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  EGLSurface s = egl().CreatePbufferSurface(d.display, d.config, surface_attribs);
  if (s == EGL_NO_SURFACE) throw std::runtime_error(egl_error("eglCreatePbufferSurface"));
  const Current before = save_current();
  if (!egl().MakeCurrent(d.display, s, s, reader_context(d))) {
    const std::string why = egl_error("eglMakeCurrent (the reader, clearing a new pbuffer)");
    restore_current(before, d.display);
    egl().DestroySurface(d.display, s);
    throw std::runtime_error(why);
  }
  gl<void (*)(GLclampd)>("glClearDepth")(0.0);  // the reader's own state: it only ever clears to 0
  gl<void (*)(GLbitfield)>("glClear")(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  finish_current();
  restore_current(before, d.display);
  return s;
}

}  // namespace

bool EglContext::available(std::string* why) {
  const Display& d = display();
  if (why) *why = d.why;
  return d.display != EGL_NO_DISPLAY;
}

EglContext::EglContext(const EglRequest& r) : width_(r.width), height_(r.height) {
  if (r.width <= 0 || r.height <= 0 || r.width > 16384 || r.height > 16384)
    throw std::runtime_error("egl: framebuffer size " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                             " is outside 1..16384");
  const Display& d = display();
  if (d.display == EGL_NO_DISPLAY) throw std::runtime_error(d.why);
  if (!egl().BindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI(EGL_OPENGL_API)"));
  const EGLint profile = r.profile == Profile::Core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                                    : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, r.major, EGL_CONTEXT_MINOR_VERSION, r.minor,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, profile, EGL_NONE};
  EGLSurface surface;
  {
    std::lock_guard<std::mutex> lock(reader_mutex);
    surface = make_pbuffer(d, r.width, r.height);
  }
  EGLContext context = egl().CreateContext(d.display, d.context_config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT) {
    const std::string why = egl_error(r.profile == Profile::Core ? "eglCreateContext (core profile)"
                                                                 : "eglCreateContext (compatibility profile)");
    egl().DestroySurface(d.display, surface);
    throw std::runtime_error(why);
  }
  platform_ = d.platform;
  display_ = d.display;
  config_ = d.config;
  surface_ = surface;
  context_ = context;
  make_current();
}

EglContext::~EglContext() {
  if (!display_) return;
  const bool current = is_current();
  const Current before = save_current();
  if (bind(display_, surface_, context_)) finish_current();
  if (current)
    egl().MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  else
    restore_current(before, display_);
  egl().DestroyContext(display_, context_);
  egl().DestroySurface(display_, surface_);
}

void EglContext::make_current() {
  if (!bind(display_, surface_, context_)) throw std::runtime_error(egl_error("eglMakeCurrent"));
}

void EglContext::release() {
  const EglApi& a = egl();
  if (!a.error.empty() || !a.BindAPI(EGL_OPENGL_API)) return;
  if (EGLDisplay d = a.GetCurrentDisplay(); d != EGL_NO_DISPLAY)
    a.MakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

bool EglContext::is_current() const {
  if (!context_) return false;
  const EGLenum api = egl().QueryAPI();
  egl().BindAPI(EGL_OPENGL_API);  // eglGetCurrentContext answers for the bound API
  const bool current = egl().GetCurrentContext() == context_;
  egl().BindAPI(api);
  return current;
}

void EglContext::resize(int width, int height) {
  const Display& d = display();
  EGLSurface fresh;
  {
    std::lock_guard<std::mutex> lock(reader_mutex);
    fresh = make_pbuffer(d, width, height);  // throws for a bad size, nothing changed
  }
  const bool current = is_current();
  const Current before = save_current();
  if (bind(display_, surface_, context_)) finish_current();
  if (!egl().MakeCurrent(display_, fresh, fresh, context_)) {
    const std::string why = egl_error("eglMakeCurrent (the resized pbuffer)");
    egl().DestroySurface(display_, fresh);
    restore_current(before, display_);
    throw std::runtime_error(why);
  }
  egl().DestroySurface(display_, surface_);
  surface_ = fresh;
  width_ = width, height_ = height;
  if (!current) restore_current(before, display_);
}

void EglContext::read_rgba(std::uint8_t* out) {
  const Display& d = display();
  std::lock_guard<std::mutex> lock(reader_mutex);
  EGLContext reader = reader_context(d);
  const Current before = save_current();
  if (!bind(display_, surface_, context_)) {
    const std::string why = egl_error("eglMakeCurrent");
    restore_current(before, display_);
    throw std::runtime_error(why);
  }
  finish_current();
  if (!egl().MakeCurrent(display_, surface_, surface_, reader)) {
    const std::string why = egl_error("eglMakeCurrent (the reader)");
    restore_current(before, display_);
    throw std::runtime_error(why);
  }
  // Rows of width * 4 bytes: GL's default pack alignment (4) adds no padding.
  using ReadPixels = void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
  gl<ReadPixels>("glReadPixels")(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out);
  const size_t row = size_t(width_) * 4;
  for (int y = 0; y < height_ / 2; ++y)  // GL's rows are bottom-up; flipped in place
    std::swap_ranges(out + size_t(y) * row, out + size_t(y + 1) * row, out + size_t(height_ - 1 - y) * row);
  restore_current(before, display_);
}

void* EglContext::proc_address(const char* name) {
  const EglApi& a = egl();
  return a.error.empty() ? reinterpret_cast<void*>(a.GetProcAddress(name)) : nullptr;
}

std::string EglContext::description() const {
  const char* vendor = egl().QueryString(display_, EGL_VENDOR);
  const char* version = egl().QueryString(display_, EGL_VERSION);
  return std::string("EGL ") + (version ? version : "?") + " (" + (vendor ? vendor : "?") + "), " + platform_ +
         " platform";
}

}  // namespace ffc::platform
