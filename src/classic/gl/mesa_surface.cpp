#include "mesa_surface.h"

#include <stdexcept>

#include "platform/platform_choice.h"
#ifdef FFCOMPAT_CLASSIC_OSMESA
#include "osmesa.h"
#endif
#ifdef FFCOMPAT_CLASSIC_EGL
#include "egl_surface.h"
#endif

namespace ffc::classic {

#ifdef FFCOMPAT_CLASSIC_OSMESA
constexpr bool kOsMesa = true;
#else
constexpr bool kOsMesa = false;
#endif
#ifdef FFCOMPAT_CLASSIC_EGL
constexpr bool kEgl = true;
#else
constexpr bool kEgl = false;
#endif

std::unique_ptr<MesaSurface> make_mesa_surface(int width, int height, std::string& platform, std::string& why) {
  try {
    platform = platform::mesa_platform_from_environment(kOsMesa, kEgl);
  } catch (const std::invalid_argument& e) {
    why = e.what();
    return nullptr;
  }
#ifdef FFCOMPAT_CLASSIC_OSMESA
  if (platform == "osmesa") return OsMesaSurface::make(width, height, why);
#endif
#ifdef FFCOMPAT_CLASSIC_EGL
  if (platform == "egl") return make_egl_surface(width, height, why);
#endif
  (void)width, (void)height;
  why = "platform '" + platform + "' is not built";
  return nullptr;
}

}  // namespace ffc::classic
