// The platform part of the Mesa backend: how a Mesa context with a width x height RGBA8 + depth 24
// framebuffer is made, made current, read back and destroyed. OSMesa (osmesa_platform.cpp, built
// with FFCOMPAT_WITH_OSMESA) and EGL (egl_platform.cpp, on platform::EglContext, built with
// FFCOMPAT_WITH_EGL) give the same llvmpipe; platform_choice.h says which one a backend takes.
#pragma once
#include <memory>
#include <string>

#include "image/image.h"

namespace ffc::backends::mesa {

class Platform {
 public:
  // Destroying the context finishes its queued drawing first (see osmesa_platform.cpp).
  virtual ~Platform() = default;
  // Makes the context and its framebuffer current on this thread. Throws std::runtime_error.
  virtual void make_current() = 0;
  // Finishes the drawing and copies the colour buffer, top row first, whatever the pixel-store
  // state the drawing left.
  virtual void read(image::Image& out) = 0;
};

using Loader = void* (*)(const char* name);

// A compatibility context (the fixed-function pipeline is what we compare against), current.
// Throws std::runtime_error naming what failed.
std::unique_ptr<Platform> make_osmesa(int width, int height);
std::unique_ptr<Platform> make_egl(int width, int height);
// Each platform's GL entry points by name.
void* osmesa_proc_address(const char* name);
void* egl_proc_address(const char* name);

}  // namespace ffc::backends::mesa
