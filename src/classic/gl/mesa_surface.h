// The mesa backend of libGL.so.1: a Mesa context on OSMesa (osmesa.h) or EGL (egl_surface.h),
// each library loaded with dlopen into a scope of its own, so that their symbols never meet the
// program's gl* names (ours). The platform is chosen as the in-process Mesa backend chooses it
// (src/platform/platform_choice.h): FFCOMPAT_PLATFORM, else OSMesa where built, else EGL.
#pragma once
#include <memory>
#include <string>

#include "table.h"

namespace ffc::classic {

class MesaSurface {
 public:
  // Finishes the queued drawing before the context goes (Mesa 22.3 crashes otherwise).
  virtual ~MesaSurface() = default;
  virtual bool make_current() = 0;
  // Leaves no context of this platform current on the thread (a window's own EGL context is
  // about to be made current).
  virtual void release() {}
  // A new framebuffer, the context's state kept: the queued drawing is finished into the old one.
  virtual void resize(int width, int height) = 0;
  // Each entry point by the platform's GetProcAddress.
  virtual void fill(Table& table) const = 0;
  // Finishes drawing and copies the picture, top row first.
  virtual void read_rgba(unsigned char* out) = 0;
};

// A width x height RGBA context with a 24-bit depth buffer on the chosen platform, made current;
// `platform` says which. Null with `why` set when the platform is unknown, not built, or its
// library or context cannot be had.
std::unique_ptr<MesaSurface> make_mesa_surface(int width, int height, std::string& platform, std::string& why);

}  // namespace ffc::classic
