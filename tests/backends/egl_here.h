// Whether an EGL display can be opened here (the GLSL backend's tests skip without one, saying why).
#pragma once
#include <cstdio>
#include <string>

#include "platform/egl_context.h"

namespace ffc::test {

inline bool egl_here() {
  std::string why;
  if (platform::EglContext::available(&why)) return true;
  std::fprintf(stderr, "no EGL display: %s\n", why.c_str());
  return false;
}

}  // namespace ffc::test
