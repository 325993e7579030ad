// The rule that picks the Mesa backend's platform (platform_choice.h), for every combination of
// built platforms and forced names.
#include "platform/platform_choice.h"

#include <gtest/gtest.h>

#include <string>

namespace ffc::platform {
namespace {

std::string refusal(bool osmesa, bool egl, const char* forced) {
  try {
    choose_mesa_platform(osmesa, egl, forced);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(PlatformChoice, OsMesaWhereBuiltElseEgl) {
  EXPECT_EQ(choose_mesa_platform(true, true, nullptr), "osmesa");
  EXPECT_EQ(choose_mesa_platform(true, false, nullptr), "osmesa");
  EXPECT_EQ(choose_mesa_platform(false, true, nullptr), "egl");
  EXPECT_EQ(choose_mesa_platform(false, true, ""), "egl");  // an empty variable forces nothing
}

TEST(PlatformChoice, ABuiltPlatformCanBeForced) {
  EXPECT_EQ(choose_mesa_platform(true, true, "egl"), "egl");
  EXPECT_EQ(choose_mesa_platform(true, true, "osmesa"), "osmesa");
  EXPECT_EQ(choose_mesa_platform(false, true, "egl"), "egl");
}

TEST(PlatformChoice, ErrorsNameTheProblem) {
  EXPECT_EQ(refusal(true, true, "glx"), "unknown Mesa platform 'glx' (FFCOMPAT_PLATFORM or --platform: osmesa or egl)");
  EXPECT_EQ(refusal(false, true, "osmesa"),
            "Mesa platform 'osmesa' is not built into this ffcompat (built: egl); OSMesa (libosmesa6-dev) was not "
            "found at configure time or was switched off");
  EXPECT_EQ(refusal(true, false, "egl"),
            "Mesa platform 'egl' is not built into this ffcompat (built: osmesa); EGL (libegl-dev) was not found at "
            "configure time or was switched off");
  EXPECT_EQ(refusal(false, false, nullptr), "no Mesa platform is built: neither OSMesa nor EGL was found at configure time");
  EXPECT_EQ(refusal(false, false, "egl"), refusal(false, false, nullptr));
}

}  // namespace
}  // namespace ffc::platform
