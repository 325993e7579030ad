// libGL.so.1's C face: every GLAPI function of <GL/gl.h>, each a call through the current
// surface's table. gl.h's own prototypes are in scope, so a signature that differs from the
// system's header does not compile.
#define GL_GLEXT_PROTOTYPES  // gl.h's two GL_OES_EGL_image prototypes are behind it
#include <GL/gl.h>

#include <cstring>

#include "table.h"

namespace {

// What a call returns when no backend answers it: 0 of its type.
template <typename R>
R nothing() {
  return R();
}
template <>
void nothing<void>() {}

}  // namespace

#define FFC_CLASSIC_GL(R, N, P, A, G)                                           \
  extern "C" R GLAPIENTRY N P {                                             \
    using Fn = R(GLAPIENTRY*) P;                                            \
    if (void* f = ffc::classic::entry(ffc::classic::k_##N)) return reinterpret_cast<Fn>(f) A; \
    ffc::classic::unavailable(ffc::classic::k_##N);                          \
    return nothing<R>();                                                     \
  }
#include "gl_exports.inc"
#undef FFC_CLASSIC_GL

namespace ffc::classic {

void* export_address(const char* name) {
  static void* const addresses[kEntryCount] = {
#define FFC_CLASSIC_GL(R, N, P, A, G) reinterpret_cast<void*>(&::N),
#include "gl_exports.inc"
#undef FFC_CLASSIC_GL
  };
  if (!name) return nullptr;
  for (int i = 0; i < kEntryCount; ++i)
    if (std::strcmp(kEntryNames[i], name) == 0) return addresses[i];
  return nullptr;
}

}  // namespace ffc::classic
