// The GLSL backend against Mesa: every built-in configuration and shipped scene within 1e-5 of
// Mesa's lit vertex colours (the shaders' outputs through transform feedback against Mesa's
// feedback) and within one 8-bit step on every pixel; the program cache; flat shading's provoking
// vertices; glReadPixels.
#include <gtest/gtest.h>

#ifdef FFCOMPAT_WITH_GLSL  // a build with EGL
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "backends/glsl/glsl_backend.h"
#include "egl_here.h"
#include "backends/glsl/vertex_compare.h"
#include "gl/dispatch.h"
#include "image/compare.h"
#include "report/ideal.h"
#include "scene/file.h"
#include "scene/scene.h"

namespace ffc {
namespace {

using test::egl_here;

struct Case {
  std::string name;
  scene::Spec spec;
};

// The built-in configurations of tests/check/regression_test.cpp (the icosphere up to depth 5):
// each camera or depth, flat and smooth, with each normal source.
std::vector<Case> cases() {
  std::vector<Case> out;
  using N = mesh::NormalSource;
  auto shaded = [&out](const std::string& base, scene::Spec s, std::initializer_list<N> normals) {
    for (auto shade : {scene::Shade::Flat, scene::Shade::Smooth})
      for (N n : normals) {
        s.shade = shade, s.normals = n;
        out.push_back({base + "_" + scene::to_string(shade) + "_" + mesh::to_string(n), s});
      }
  };
  for (double angle : {0.0, 30.0, 75.0, 200.0}) {
    scene::Spec s = scene::builtin("cube");
    s.cam_angle_deg = angle, s.cam_height = angle == 0 ? 1 : 2.5;
    shaded("cube_" + std::to_string(int(angle)), s, {N::Face, N::Average});
  }
  for (int depth : {0, 1, 3, 5}) {
    scene::Spec s = scene::builtin("icosphere");
    s.depth = depth;
    shaded("icosphere_" + std::to_string(depth), s, {N::Face, N::Average, N::Sphere});
  }
  return out;
}

// Both levels against Mesa: the shaders' vertices (every primitive Mesa reports paired with ours
// or holding a clip-made vertex) within 1e-5, the pictures within one step.
void expect_agrees_with_mesa(const scene::Description& d, bool inside_view) {
  const glsl::VertexComparison r = glsl::compare_with_mesa(d.width, d.height, [&] { scene::draw(d); });
  EXPECT_GT(r.compared, 0u);
  EXPECT_EQ(r.unpaired, 0u) << "a primitive of Mesa's at our positions that we did not draw";
  EXPECT_LE(r.max_abs, 1e-5);
  EXPECT_LE(r.max_position, 1e-3);
  if (inside_view) {
    EXPECT_EQ(r.clipped, 0u);
  }
  EXPECT_TRUE(r.known_mesa_deviations.empty());
  auto mesa = backends::make("mesa"), ours = backends::make("glsl");
  EXPECT_LE(image::compare(scene::render(d, *mesa), scene::render(d, *ours)).max_diff, 1);
}

class GlslBuiltIn : public ::testing::TestWithParam<Case> {};

TEST_P(GlslBuiltIn, VertexColoursWithin1e5AndPixelsWithinOneStepOfMesa) {
  if (!egl_here()) GTEST_SKIP();
  expect_agrees_with_mesa(scene::describe(GetParam().spec), true);  // the built-in scenes lie inside the view
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlslBuiltIn, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

// Every scene file shipped in scenes/ (clipped floors among them).
std::vector<std::string> shipped() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(FFCOMPAT_SOURCE_DIR) + "/scenes"))
    if (e.path().extension() == ".toml") out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

class GlslShipped : public ::testing::TestWithParam<std::string> {};

TEST_P(GlslShipped, VertexColoursWithin1e5AndPixelsWithinOneStepOfMesa) {
  if (!egl_here()) GTEST_SKIP();
  expect_agrees_with_mesa(scene::load_file(std::string(FFCOMPAT_SOURCE_DIR) + "/scenes/" + GetParam() + ".toml"), false);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlslShipped, ::testing::ValuesIn(shipped()));

// Every primitive mode, immediate mode with per-vertex normals and colours, glArrayElement, a
// display list, two-sided lighting with colour material and a local viewer: both levels as Mesa.
void every_mode(GLenum shade) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glRotatef(20, 1, 1, 0);
  glShadeModel(shade);
  glEnable(GL_LIGHTING), glEnable(GL_LIGHT0), glEnable(GL_LIGHT1);
  const float p1[4] = {0.5f, 0.5f, 1, 1}, d1[4] = {0.9f, 0.6f, 0.3f, 1}, s1[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT1, GL_POSITION, p1), glLightfv(GL_LIGHT1, GL_DIFFUSE, d1), glLightfv(GL_LIGHT1, GL_SPECULAR, s1);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.5f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1), glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  const float spec[4] = {0.6f, 0.6f, 0.6f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec), glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
  glEnable(GL_COLOR_MATERIAL), glEnable(GL_NORMALIZE);
  const GLenum modes[] = {GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_STRIP,
                          GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
  glPointSize(3);
  for (int m = 0; m < 10; ++m) {
    const float x0 = -0.9f + 0.36f * float(m % 5), y0 = m < 5 ? 0.1f : -0.8f;
    glBegin(modes[m]);
    for (int i = 0; i < 8; ++i) {
      const float a = 0.8f * float(i);
      glColor3f(0.3f + 0.08f * float(i), 0.9f - 0.1f * float(i), 0.5f);
      glNormal3f(std::cos(a), std::sin(a), i % 2 ? 1.0f : -0.5f);
      // A zigzag for the strips, a circle for fans and polygons.
      const bool round = modes[m] == GL_TRIANGLE_FAN || modes[m] == GL_POLYGON;
      glVertex2f(x0 + (round ? 0.15f + 0.14f * std::cos(a) : 0.04f * float(i)),
                 y0 + (round ? 0.3f + 0.3f * std::sin(a) : 0.35f * float(i % 2) + 0.05f * float(i / 2)));
    }
    glEnd();
  }
  static const float tri[9] = {-0.2f, -0.1f, 0.3f, 0.2f, -0.1f, 0.1f, 0.0f, 0.1f, -0.2f};
  glVertexPointer(3, GL_FLOAT, 0, tri);
  glEnableClientState(GL_VERTEX_ARRAY);
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; ++i) glArrayElement(i);
  glEnd();
  glEndList();
  glColor3f(0.2f, 0.4f, 1.0f);
  glCallList(1);
}

TEST(GlslBackend, EveryPrimitiveModeAgreesWithMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum shade : {GL_FLAT, GL_SMOOTH}) {
    SCOPED_TRACE(shade == GL_FLAT ? "flat" : "smooth");
    const glsl::VertexComparison r = glsl::compare_with_mesa(96, 96, [&] { every_mode(shade); });
    // points 8, lines 4, line strip 7, loop 8, triangles 2, strip 6, fan 6, quads 4, quad strip 6,
    // polygon 6, the listed triangle 1
    EXPECT_EQ(r.compared, 58u);
    EXPECT_EQ(r.unpaired, 0u);
    EXPECT_EQ(r.clipped, 0u);
    EXPECT_LE(r.max_abs, 1e-5);
    auto mesa = backends::make("mesa"), ours = backends::make("glsl");
    mesa->begin(96, 96), ours->begin(96, 96);
    ours->resume(), every_mode(shade);
    const image::Image b = ours->read();
    mesa->resume(), every_mode(shade);
    EXPECT_LE(image::compare(mesa->read(), b).max_diff, 1);
  }
}

// Per-fragment lighting comes closer to the exact sphere lit per pixel (report::ray_cast_sphere)
// than GL's per-vertex lighting of the same coarse icosphere, inside the silhouette (measured:
// mean error 1.27 steps against 2.49).
TEST(GlslBackend, PhongShadingIsCloserToTheExactSphereThanGouraud) {
  if (!egl_here()) GTEST_SKIP();
  scene::Spec s = scene::builtin("icosphere");
  s.depth = 2, s.shade = scene::Shade::Smooth, s.normals = mesh::NormalSource::Sphere;
  const scene::Description d = scene::describe(s);
  const report::Ideal ideal = report::ray_cast_sphere(d);
  backends::GlslBackend gouraud(false), phong(true);
  auto error = [&](backends::Backend& b) {
    const image::Image img = scene::render(d, b);
    // Inside the silhouette by 8 pixels: the mesh's outline is not the sphere's, whatever the shading.
    auto inside = [&](int x, int y) {
      return x >= 0 && y >= 0 && x < d.width && y < d.height && ideal.covered[size_t(y) * size_t(d.width) + size_t(x)];
    };
    double sum = 0;
    size_t n = 0;
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) {
        if (!inside(x, y) || !inside(x - 8, y) || !inside(x + 8, y) || !inside(x, y - 8) || !inside(x, y + 8)) continue;
        const size_t i = 4 * (size_t(y) * size_t(d.width) + size_t(x));
        for (int c = 0; c < 3; ++c) sum += std::abs(int(img.rgba[i + size_t(c)]) - int(ideal.image.rgba[i + size_t(c)]));
        n += 3;
      }
    return sum / double(n);
  };
  const double eg = error(gouraud), ep = error(phong);
  EXPECT_EQ(phong.name(), "glsl-phong");
  EXPECT_LT(ep, 0.6 * eg) << "mean step error: phong " << ep << ", gouraud " << eg;
}

// OSMesa and EGL share Mesa's dispatch: frames taken in turns with Mesa (as ffcompat bench does)
// draw the GLSL backend's own picture (the calls once reached OSMesa's context and crashed).
TEST(GlslBackend, FramesInTurnsWithMesaDrawItsOwnPicture) {
  if (!egl_here()) GTEST_SKIP();
  const scene::Spec s = scene::builtin("cube");
  auto alone = backends::make("glsl");
  const image::Image want = scene::render(s, *alone);
  auto mesa = backends::make("mesa"), ours = backends::make("glsl");
  ours->begin(s.width, s.height), mesa->begin(s.width, s.height);
  for (int turn = 0; turn < 2; ++turn) {
    mesa->resume(), scene::draw(s);
    const image::Image m = mesa->read();
    ours->resume(), scene::draw(s);
    EXPECT_EQ(image::compare(want, ours->read()).max_diff, 0);
    EXPECT_LE(image::compare(m, want).max_diff, 1);
  }
}

TEST(GlslBackend, OneProgramPerKeyThenCacheHits) {
  if (!egl_here()) GTEST_SKIP();
  backends::GlslBackend b;
  const scene::Spec s = scene::builtin("cube");  // two draws: one unlit, the lit cube (key 20000101/100)
  scene::render(s, b);
  const glsl::Stats first = b.renderer()->stats();
  EXPECT_EQ(first.draws, 2u);
  EXPECT_EQ(first.compiles, 2u);
  EXPECT_EQ(first.cache_hits, 0u);
  scene::draw(s);  // the same frame again: nothing new to compile, nor any uniform to send
  const glsl::Stats second = b.renderer()->stats();
  EXPECT_EQ(second.compiles, 2u);
  EXPECT_EQ(second.cache_hits, 2u);
  EXPECT_EQ(second.uniform_uploads, first.uniform_uploads);
}

// Unlit, four corner colours: a flat quad takes its 4th vertex's colour, a flat polygon its 1st.
TEST(GlslBackend, FlatShadingTakesGlsProvokingVertex) {
  if (!egl_here()) GTEST_SKIP();
  backends::GlslBackend b;
  b.begin(32, 32);
  glShadeModel(GL_FLAT);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const float c[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  const float p[4][2] = {{-1, -1}, {0, -1}, {0, 1}, {-1, 1}};
  glBegin(GL_QUADS);  // left half
  for (int i = 0; i < 4; ++i) glColor3fv(c[i]), glVertex2fv(p[i]);
  glEnd();
  glBegin(GL_POLYGON);  // right half
  for (int i = 0; i < 4; ++i) glColor3fv(c[i]), glVertex2f(p[i][0] + 1, p[i][1]);
  glEnd();
  const image::Image img = b.read();
  auto rgb = [&img](int x, int y) {
    const uint8_t* p = img.at(x, y);
    return std::vector<int>{p[0], p[1], p[2]};
  };
  for (int y : {4, 16, 28}) {
    EXPECT_EQ(rgb(8, y), (std::vector<int>{255, 255, 0}));  // the quad's 4th: yellow
    EXPECT_EQ(rgb(24, y), (std::vector<int>{255, 0, 0}));   // the polygon's 1st: red
  }
}

TEST(GlslBackend, ReadPixelsReadsTheShadersPicture) {
  if (!egl_here()) GTEST_SKIP();
  backends::GlslBackend b;
  b.begin(4, 4);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  uint8_t px[4] = {};
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ((std::vector<int>{px[0], px[1], px[2], px[3]}), (std::vector<int>{0, 255, 0, 255}));
  // GL's rows, the bottom one first (they once came upside down).
  glColor3f(1, 0, 0);
  glRectf(-1, -1, 1, 0);  // the bottom half
  uint8_t low[4] = {}, high[4] = {};
  glReadPixels(2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, low);
  glReadPixels(2, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, high);
  EXPECT_EQ(low[0], 255);
  EXPECT_EQ(high[0], 0);
}

}  // namespace
}  // namespace ffc
#endif  // FFCOMPAT_WITH_GLSL
