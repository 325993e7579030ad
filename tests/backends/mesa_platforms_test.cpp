// The Mesa backend on its two platforms: OSMesa and EGL reach the same llvmpipe, so every picture
// and every fed-back vertex must be the same, byte for byte and float for float; and the choice
// of platform (FFCOMPAT_PLATFORM, the constructor's argument) with its errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "backends/mesa/mesa_backend.h"
#include "check/feedback.h"
#include "gl/dispatch.h"
#include "scene/description.h"
#include "scene/scene.h"

namespace ffc {
namespace {

bool built(const std::string& platform) {
  for (const std::string& p : backends::mesa_platforms())
    if (p == platform) return true;
  return false;
}

// Both platforms, or the test is skipped saying which is missing (a build without OSMesa: the
// choice tests below still run).
#define REQUIRE_BOTH_PLATFORMS()                                                                   \
  do {                                                                                             \
    if (!built("osmesa") || !built("egl")) GTEST_SKIP() << "needs both OSMesa and EGL in the build"; \
  } while (0)

// Sets FFCOMPAT_PLATFORM for one scope.
struct PlatformVariable {
  explicit PlatformVariable(const char* value) {
    if (const char* old = std::getenv("FFCOMPAT_PLATFORM")) saved = old, had = true;
    if (value)
      setenv("FFCOMPAT_PLATFORM", value, 1);
    else
      unsetenv("FFCOMPAT_PLATFORM");
  }
  ~PlatformVariable() {
    if (had)
      setenv("FFCOMPAT_PLATFORM", saved.c_str(), 1);
    else
      unsetenv("FFCOMPAT_PLATFORM");
  }
  std::string saved;
  bool had = false;
};

// The built-in scenes in shade models, normals and draw paths that take different routes through
// Mesa (arrays, elements, immediate mode; flat and smooth).
std::vector<scene::Description> configurations() {
  std::vector<scene::Description> out;
  for (const char* name : {"cube", "icosphere"})
    for (scene::Shade shade : {scene::Shade::Flat, scene::Shade::Smooth})
      for (const char* normals : {"face", "average"})
        for (scene::DrawPath path : {scene::DrawPath::Auto, scene::DrawPath::Immediate}) {
          scene::Spec spec = scene::builtin(name);
          spec.shade = shade;
          spec.width = 96, spec.height = 80;  // not square: rows and columns cannot be swapped unseen
          scene::Description d = scene::describe(spec);
          for (scene::Object& o : d.objects) {
            scene::set_normals(o, normals);
            o.draw = path;
          }
          out.push_back(d);
        }
  return out;
}

std::string label(const scene::Description& d) {
  return d.name + " " + scene::to_string(d.shade) + " " + scene::normals_name(d.objects.front()) + " draw " +
         std::to_string(int(d.objects.front().draw));
}

TEST(MesaPlatforms, PicturesAreTheSameBytes) {
  REQUIRE_BOTH_PLATFORMS();
  backends::MesaBackend osmesa("osmesa"), egl("egl");
  for (const scene::Description& d : configurations()) {
    SCOPED_TRACE(label(d));
    const image::Image a = scene::render(d, osmesa), b = scene::render(d, egl);
    ASSERT_EQ(a.width, 96);
    ASSERT_EQ(a.height, 80);
    ASSERT_EQ(b.width, a.width);
    ASSERT_EQ(b.height, a.height);
    // Something was drawn: the lit object covers pixels beyond the clear colour.
    size_t lit = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) lit += a.rgba[i] + a.rgba[i + 1] + a.rgba[i + 2] > 60;
    EXPECT_GT(lit, 500u);
    EXPECT_TRUE(a.rgba == b.rgba) << "the pictures differ";
  }
}

TEST(MesaPlatforms, FeedbackIsTheSameFloats) {
  REQUIRE_BOTH_PLATFORMS();
  backends::MesaBackend osmesa("osmesa"), egl("egl");
  for (const scene::Description& d : configurations()) {
    SCOPED_TRACE(label(d));
    auto draw = [&] { scene::draw(d); };
    const auto a = check::capture(osmesa, d.width, d.height, draw);
    const auto b = check::capture(egl, d.width, d.height, draw);
    ASSERT_GT(a.size(), 10u);
    ASSERT_EQ(a.size(), b.size());
    for (size_t p = 0; p < a.size(); ++p) {
      ASSERT_EQ(a[p].token, b[p].token) << "primitive " << p;
      ASSERT_EQ(a[p].vertices.size(), b[p].vertices.size()) << "primitive " << p;
      for (size_t v = 0; v < a[p].vertices.size(); ++v) {
        // The values are floats widened to double: == compares the floats bit for bit.
        EXPECT_EQ(a[p].vertices[v].position, b[p].vertices[v].position) << "primitive " << p << " vertex " << v;
        EXPECT_EQ(a[p].vertices[v].color, b[p].vertices[v].color) << "primitive " << p << " vertex " << v;
      }
    }
  }
}

// The EGL platform reads its pbuffer with a context of its own: the drawing context's pixel-store
// and pixel-transfer state cannot change the picture, as it cannot OSMesa's buffer in memory.
TEST(MesaPlatforms, ReadBackIgnoresTheDrawingContextsPixelState) {
  for (const std::string& platform : backends::mesa_platforms()) {
    SCOPED_TRACE(platform);
    backends::MesaBackend mesa(platform);
    mesa.begin(7, 5);  // 7 * 4 = 28 bytes a row: a pack alignment of 8 would pad it
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 11);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    // Not in the dispatch (no backend of ours has it): straight from the platform.
    auto pixel_transfer =
        reinterpret_cast<void (*)(GLenum, GLfloat)>(backends::mesa_proc_address(platform, "glPixelTransferf"));
    ASSERT_NE(pixel_transfer, nullptr);
    pixel_transfer(GL_RED_SCALE, 0.0f);
    const image::Image img = mesa.read();
    ASSERT_EQ(img.rgba.size(), 7u * 5 * 4);
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
      ASSERT_EQ(img.rgba[i], 51) << "pixel " << i / 4;  // 0.2 * 255
      ASSERT_EQ(img.rgba[i + 1], 102) << "pixel " << i / 4;
      ASSERT_EQ(img.rgba[i + 2], 153) << "pixel " << i / 4;
      ASSERT_EQ(img.rgba[i + 3], 255) << "pixel " << i / 4;
    }
  }
}

// Top row first on both: a clear of the top half only (scissored) lands in the first rows.
TEST(MesaPlatforms, RowsComeTopFirst) {
  for (const std::string& platform : backends::mesa_platforms()) {
    SCOPED_TRACE(platform);
    backends::MesaBackend mesa(platform);
    mesa.begin(4, 6);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 3, 4, 3);  // GL's rows 3..5: the top half
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    const image::Image img = mesa.read();
    EXPECT_EQ(img.at(0, 0)[0], 255);
    EXPECT_EQ(img.at(3, 2)[0], 255);
    EXPECT_EQ(img.at(0, 3)[0], 0);
    EXPECT_EQ(img.at(3, 5)[0], 0);
  }
}

// Two Mesa backends on the two platforms taking turns, as `ffcompat bench` alternates backends:
// each keeps its own state and pixels across the other's frames.
TEST(MesaPlatforms, BackendsOnBothPlatformsTakeTurns) {
  REQUIRE_BOTH_PLATFORMS();
  backends::MesaBackend a("osmesa"), b("egl");
  a.begin(8, 8);
  glClearColor(1, 0, 0, 1);
  b.begin(8, 8);
  glClearColor(0, 0, 1, 1);
  for (int round = 0; round < 3; ++round) {
    a.resume();
    glClear(GL_COLOR_BUFFER_BIT);  // red: a's clear colour survived b's frames
    b.resume();
    glClear(GL_COLOR_BUFFER_BIT);
    const image::Image pa = a.read(), pb = b.read();
    EXPECT_EQ(pa.at(4, 4)[0], 255);
    EXPECT_EQ(pa.at(4, 4)[2], 0);
    EXPECT_EQ(pb.at(4, 4)[0], 0);
    EXPECT_EQ(pb.at(4, 4)[2], 255);
  }
}

TEST(MesaPlatformChoice, EnvironmentPicksThePlatform) {
  const std::vector<std::string> platforms = backends::mesa_platforms();
  ASSERT_FALSE(platforms.empty());
  {
    PlatformVariable none(nullptr);
    // OSMesa where built, else EGL.
    EXPECT_EQ(backends::mesa_platform(), built("osmesa") ? "osmesa" : "egl");
  }
  for (const std::string& p : platforms) {
    PlatformVariable forced(p.c_str());
    EXPECT_EQ(backends::mesa_platform(), p);
    auto mesa = backends::make("mesa");
    EXPECT_EQ(mesa->name(), "mesa");  // the backend's name does not change with the platform
    EXPECT_EQ(static_cast<backends::MesaBackend&>(*mesa).platform(), p);
    mesa->begin(2, 2);
    EXPECT_NE(backends::mesa_proc_address(p, "glLightiv"), nullptr);
  }
}

TEST(MesaPlatformChoice, UnknownAndUnbuiltPlatformsAreRefused) {
  {
    PlatformVariable bogus("vulkan");
    try {
      backends::make("mesa");
      FAIL() << "FFCOMPAT_PLATFORM=vulkan was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("unknown Mesa platform 'vulkan'"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(backends::MesaBackend("OSMesa"), std::invalid_argument);  // names are lower case
  for (const char* p : {"osmesa", "egl"}) {
    if (built(p)) {
      EXPECT_NO_THROW(backends::MesaBackend{p});
      continue;
    }
    try {
      backends::MesaBackend mesa(p);
      FAIL() << p << " is not built but was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("Mesa platform '") + p + "' is not built"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace ffc
