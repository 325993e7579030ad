#include "platform/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace ffc::platform {

namespace {

std::string egl_error(const char* what) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", unsigned(eglGetError()));
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
// end every context on it at once, and the contexts come and go independently.
struct Display {
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string platform, why;
};

Display open_display() {
  Display d;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  // The device platform: Mesa's software device (llvmpipe) first, the pictures this project
  // compares against; another device (a GPU's) only when there is no software one.
  if (get_platform_display && has_extension(client, "EGL_EXT_platform_device")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto query_device_string =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
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
  if (d.display != EGL_NO_DISPLAY && !eglInitialize(d.display, nullptr, nullptr)) d.display = EGL_NO_DISPLAY;
  if (d.display == EGL_NO_DISPLAY && get_platform_display && has_extension(client, "EGL_MESA_platform_surfaceless")) {
    d.display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    d.platform = "surfaceless";
    if (d.display != EGL_NO_DISPLAY && !eglInitialize(d.display, nullptr, nullptr)) d.display = EGL_NO_DISPLAY;
  }
  if (d.display == EGL_NO_DISPLAY) {
    d.display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    d.platform = "default";
    if (d.display != EGL_NO_DISPLAY && !eglInitialize(d.display, nullptr, nullptr)) d.display = EGL_NO_DISPLAY;
  }
  if (d.display == EGL_NO_DISPLAY) {
    d.why = egl_error("no headless display (device, surfaceless or default): eglInitialize");
    return d;
  }
  // "OpenGL_ES" alone does not give desktop GL.
  const char* apis = eglQueryString(d.display, EGL_CLIENT_APIS);
  bool desktop = false;
  for (const char* p = apis; p && (p = std::strstr(p, "OpenGL")); p += 6)
    if (std::strncmp(p, "OpenGL_ES", 9) != 0) desktop = true;
  if (!desktop) {
    d.why = std::string("egl: the ") + d.platform + " display offers no desktop OpenGL (client APIs: " +
            (apis ? apis : "none") + ")";
    d.display = EGL_NO_DISPLAY;
  }
  return d;
}

const Display& display() {
  static std::once_flag once;
  static Display d;
  std::call_once(once, [] { d = open_display(); });
  return d;
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
  platform_ = d.platform;
  display_ = d.display;
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI(EGL_OPENGL_API)"));
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                   EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                   EGL_DEPTH_SIZE, 24, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(d.display, config_attribs, &config, 1, &configs) || configs < 1)
    throw std::runtime_error(egl_error("eglChooseConfig (RGBA8, depth 24, pbuffer, OpenGL)"));
  const EGLint surface_attribs[] = {EGL_WIDTH, r.width, EGL_HEIGHT, r.height, EGL_NONE};
  surface_ = eglCreatePbufferSurface(d.display, config, surface_attribs);
  if (surface_ == EGL_NO_SURFACE) throw std::runtime_error(egl_error("eglCreatePbufferSurface"));
  const EGLint profile = r.profile == Profile::Core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                                    : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, r.major, EGL_CONTEXT_MINOR_VERSION, r.minor,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, profile, EGL_NONE};
  context_ = eglCreateContext(d.display, config, EGL_NO_CONTEXT, context_attribs);
  if (context_ == EGL_NO_CONTEXT) {
    eglDestroySurface(d.display, surface_);
    surface_ = nullptr;
    throw std::runtime_error(egl_error(r.profile == Profile::Core ? "eglCreateContext (core profile)"
                                                                  : "eglCreateContext (compatibility profile)"));
  }
  make_current();
}

EglContext::~EglContext() {
  if (!display_) return;
  if (is_current()) {
    // Drains llvmpipe's queue before the buffers go (as for OSMesa, see mesa_backend.cpp).
    using Finish = void (*)();
    if (auto finish = reinterpret_cast<Finish>(eglGetProcAddress("glFinish"))) finish();
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (context_) eglDestroyContext(display_, context_);
  if (surface_) eglDestroySurface(display_, surface_);
}

void EglContext::make_current() {
  if (!eglBindAPI(EGL_OPENGL_API) || !eglMakeCurrent(display_, surface_, surface_, context_))
    throw std::runtime_error(egl_error("eglMakeCurrent"));
}

bool EglContext::is_current() const { return context_ && eglGetCurrentContext() == context_; }

void* EglContext::proc_address(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

std::string EglContext::description() const {
  const char* vendor = eglQueryString(display_, EGL_VENDOR);
  const char* version = eglQueryString(display_, EGL_VERSION);
  return std::string("EGL ") + (version ? version : "?") + " (" + (vendor ? vendor : "?") + "), " + platform_ +
         " platform";
}

}  // namespace ffc::platform
