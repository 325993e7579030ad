// Which platform gives the Mesa backend its contexts: OSMesa (Mesa's offscreen library, removed in
// Mesa 25.1) or EGL (egl_context.h). Both reach the same llvmpipe, so the pictures and feedback are
// the same (tests/backends/mesa_platforms_test.cpp); the choice only says how the context is made.
// Header only: the in-process Mesa backend (src/backends/mesa) and the classic libGL.so.1
// (src/classic/gl) choose by the same rule without sharing a library.
#pragma once
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace ffc::platform {

// The environment variable that forces a platform; `--platform` of the command line sets it, so
// programs started by `ffcompat run` follow it too.
inline constexpr const char* kPlatformVariable = "FFCOMPAT_PLATFORM";

// "osmesa" where it is built, else "egl"; `forced` (FFCOMPAT_PLATFORM's value, null or empty for
// none) picks one. Throws std::invalid_argument naming the problem: an unknown name, a platform
// this build lacks, or no platform at all.
inline std::string choose_mesa_platform(bool osmesa_built, bool egl_built, const char* forced) {
  std::string built = osmesa_built ? "osmesa" : "";
  if (egl_built) built += built.empty() ? "egl" : " and egl";
  if (built.empty())
    throw std::invalid_argument("no Mesa platform is built: neither OSMesa nor EGL was found at configure time");
  if (forced && *forced) {
    const std::string name = forced;
    if (name != "osmesa" && name != "egl")
      throw std::invalid_argument("unknown Mesa platform '" + name + "' (" + kPlatformVariable +
                                  " or --platform: osmesa or egl)");
    if ((name == "osmesa" && !osmesa_built) || (name == "egl" && !egl_built))
      throw std::invalid_argument("Mesa platform '" + name + "' is not built into this ffcompat (built: " + built +
                                  "); " + (name == "osmesa" ? "OSMesa (libosmesa6-dev)" : "EGL (libegl-dev)") +
                                  " was not found at configure time or was switched off");
    return name;
  }
  return osmesa_built ? "osmesa" : "egl";
}

inline std::string mesa_platform_from_environment(bool osmesa_built, bool egl_built) {
  return choose_mesa_platform(osmesa_built, egl_built, std::getenv(kPlatformVariable));
}

}  // namespace ffc::platform
