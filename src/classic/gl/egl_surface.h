// The EGL platform of the classic mesa backend: platform::EglContext (a compatibility context on
// a pbuffer), whose libEGL.so.1 is dlopen'ed privately (src/platform/egl_api.h).
#pragma once
#include <memory>
#include <string>

#include "mesa_surface.h"

namespace ffc::classic {

// Null with `why` set when libEGL, a display or the context cannot be had.
std::unique_ptr<MesaSurface> make_egl_surface(int width, int height, std::string& why);

}  // namespace ffc::classic
