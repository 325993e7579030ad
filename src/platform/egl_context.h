// A headless EGL context on Mesa's EGL (llvmpipe here, any driver elsewhere): the one place that
// talks to EGL. The Mesa backend takes a compatibility context from it (Mesa's fixed-function
// pipeline, as OSMesa gives it, which Mesa 25.1 removed); the GLSL backend and the seed 001
// programs take core-profile contexts. Rendering goes to a pbuffer of the requested size (RGBA8,
// 24-bit depth), so the default framebuffer, glReadPixels, feedback and selection work as in a
// window. libEGL itself is loaded on first use (egl_api.h says why).
#pragma once
#include <cstdint>
#include <string>

namespace ffc::platform {

enum class Profile { Compatibility, Core };

struct EglRequest {
  Profile profile = Profile::Compatibility;
  int major = 2, minor = 1;  // for Core: 3.3 or later
  int width = 1, height = 1;
};

class EglContext {
 public:
  // Creates the display (EGL's device platform, else the surfaceless one, else the default
  // display), a config with RGBA8 and 24-bit depth, the pbuffer and the context. Throws
  // std::runtime_error naming what failed.
  explicit EglContext(const EglRequest& request);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // Makes this context and its pbuffer current on the calling thread. Throws on failure.
  void make_current();
  // Leaves the calling thread with no OpenGL context current (of any EglContext).
  static void release();
  // A new pbuffer of this size, the context's state kept: the queued drawing is finished first,
  // and the context is current on the new pbuffer afterwards if it was current before.
  void resize(int width, int height);
  // Finishes this context's drawing and copies its pbuffer, RGBA8, top row first, into `out`
  // (width() * height() * 4 bytes). Read by a second context of the display's own, with GL's
  // default pixel-store and pixel-transfer state, so whatever the drawing context set
  // (glPixelStore, glPixelTransfer, glReadBuffer, a bound pack buffer) has no effect on it, as
  // with OSMesa's buffer in memory. The context current before is current again afterwards.
  void read_rgba(std::uint8_t* out);
  // Whether this context is the calling thread's current one.
  bool is_current() const;
  // A GL entry point of this context's API ("glBegin"), or null.
  static void* proc_address(const char* name);
  // Whether a headless EGL display with an OpenGL (not only GLES) API can be opened here; the
  // reason when not.
  static bool available(std::string* why = nullptr);
  // What the display reports: vendor, EGL version and which platform was taken ("device",
  // "surfaceless", "default").
  std::string description() const;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* surface_ = nullptr;  // EGLSurface
  void* context_ = nullptr;  // EGLContext
  std::string platform_;
  int width_ = 0, height_ = 0;
  void* config_ = nullptr;  // EGLConfig
};

}  // namespace ffc::platform
