// The GLSL backend's fixed functions after lighting, each against Mesa's fixed-function pipeline
// on the same pictures (within one 8-bit step) and against the rule GL states where the rule
// decides a pixel outright: the alpha test, fog, polygon offset, glMaterial between glBegin and
// glEnd, glPolygonMode, glDrawPixels and glBitmap.
#include <gtest/gtest.h>

#ifdef FFCOMPAT_WITH_GLSL  // a build with EGL
#include <cmath>
#include <functional>

#include "backends/glsl/glsl_backend.h"
#include "backends/glsl/vertex_compare.h"
#include "egl_here.h"
#include "glsl_pictures.h"
#include "gl/dispatch.h"
#include "image/compare.h"

namespace ffc {
namespace {

using test::draw_both;
using test::egl_here;
using test::Pictures;

void expect_as_mesa(const Pictures& p) {
  EXPECT_TRUE(p.unsupported.empty()) << p.unsupported.front();
  const image::Diff c = image::compare(p.mesa, p.glsl);
  EXPECT_LE(c.max_diff, 1);
}

std::vector<int> rgba(const image::Image& img, int x, int y) {
  const uint8_t* p = img.at(x, y);
  return {p[0], p[1], p[2], p[3]};
}

// A quad across the window whose alpha runs from 0 (left) to 1 (right), over a blue clear.
void alpha_ramp(GLenum func, float ref) {
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(func, ref);
  glBegin(GL_QUADS);
  glColor4f(1, 0.5f, 0, 0), glVertex2f(-1, -1);
  glColor4f(1, 0.5f, 0, 1), glVertex2f(1, -1);
  glColor4f(1, 0.5f, 0, 1), glVertex2f(1, 1);
  glColor4f(1, 0.5f, 0, 0), glVertex2f(-1, 1);
  glEnd();
}

TEST(GlslFeatures, AlphaTestEveryFunctionAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum func = GL_NEVER; func <= GL_ALWAYS; ++func)
    for (float ref : {0.0f, 0.3f, 0.5f, 1.0f}) {
      SCOPED_TRACE(testing::Message() << "func 0x" << std::hex << func << " ref " << ref);
      expect_as_mesa(draw_both(64, 16, [&] { alpha_ramp(func, ref); }));
    }
}

// Where the rule decides: alpha 0 at the left edge fails GL_GREATER 0.5 (the clear shows), alpha
// near 1 at the right passes (the quad's colour); GL_NEVER draws nothing, GL_ALWAYS everything.
TEST(GlslFeatures, AlphaTestKeepsAndDiscardsByTheRule) {
  if (!egl_here()) GTEST_SKIP();
  const std::vector<int> clear = {0, 0, 255, 255};
  Pictures p = draw_both(64, 16, [] { alpha_ramp(GL_GREATER, 0.5f); });
  EXPECT_EQ(rgba(p.glsl, 1, 8), clear);
  const std::vector<int> right = rgba(p.glsl, 62, 8);
  EXPECT_EQ(right[0], 255);
  EXPECT_EQ(right[1], 128);  // 0.5 * 255 = 127.5, to even
  EXPECT_EQ(right[2], 0);
  p = draw_both(64, 16, [] { alpha_ramp(GL_NEVER, 0); });
  EXPECT_EQ(rgba(p.glsl, 62, 8), clear);
  p = draw_both(64, 16, [] { alpha_ramp(GL_ALWAYS, 0); });
  EXPECT_EQ(rgba(p.glsl, 1, 8)[0], 255);
}

// A lit (or unlit, or flat) floor receding from 1.5 to 15 units, lines and points beside it, in
// perspective: the fog coordinate changes along every primitive.
void fog_scene(GLenum mode, GLenum source, GLenum shade, bool lit) {
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glShadeModel(shade);
  if (mode) glEnable(GL_FOG), glFogi(GL_FOG_MODE, GLint(mode));  // 0: no fog
  const float fog_color[4] = {0.8f, 0.7f, 0.6f, 1};
  glFogfv(GL_FOG_COLOR, fog_color);
  glFogf(GL_FOG_DENSITY, 0.15f), glFogf(GL_FOG_START, 2), glFogf(GL_FOG_END, 12);
  glFogi(GL_FOG_COORD_SRC, GLint(source));
  if (lit) glEnable(GL_LIGHTING), glEnable(GL_LIGHT0), glEnable(GL_COLOR_MATERIAL);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 6; ++i) {
    const float z = -1.5f - 2.25f * float(i);
    glNormal3f(0, 1, 0.3f * float(i % 2));
    glColor3f(0.2f + 0.1f * float(i), 0.9f - 0.1f * float(i), 0.4f);
    glVertex3f(-1.2f, -0.8f, z), glVertex3f(1.2f, -0.8f, z);
  }
  glEnd();
  glLineWidth(2);  // points of 1 pixel, off the pixel edges: see docs/glsl.md on wide points
  glBegin(GL_LINES);
  glColor3f(1, 1, 0), glVertex3f(-0.9f, 0.2f, -1.5f), glVertex3f(0.9f, 0.6f, -15);
  glEnd();
  glBegin(GL_POINTS);
  for (int i = 0; i < 6; ++i) glColor3f(0, 1, 1), glVertex3f(-0.47f + 0.2f * float(i), 0.13f, -2.0f - 2.5f * float(i));
  glEnd();
}

TEST(GlslFeatures, FogEveryModeAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum mode : {GL_LINEAR, GL_EXP, GL_EXP2})
    for (GLenum source : {GL_FRAGMENT_DEPTH, GL_FOG_COORD})
      for (GLenum shade : {GL_SMOOTH, GL_FLAT})
        for (bool lit : {false, true}) {
          SCOPED_TRACE(testing::Message() << "mode 0x" << std::hex << mode << " source 0x" << source << " shade 0x"
                                          << shade << (lit ? " lit" : " unlit"));
          expect_as_mesa(draw_both(64, 64, [&] { fog_scene(mode, source, shade, lit); }));
        }
}

// Per-fragment lighting (glsl-phong) carries the same fog and alpha test: its programs compile,
// draw, and the fog changes the picture.
TEST(GlslFeatures, PhongProgramsCarryFogAndAlphaTest) {
  if (!egl_here()) GTEST_SKIP();
  backends::GlslBackend fogged(true), clear(true);
  fogged.begin(64, 64), clear.begin(64, 64);
  auto scene = [](GLenum fog) {
    glEnable(GL_ALPHA_TEST), glAlphaFunc(GL_GREATER, 0.1f);
    fog_scene(fog, GL_FRAGMENT_DEPTH, GL_SMOOTH, true);
  };
  fogged.resume(), scene(GL_EXP2);
  const image::Image a = fogged.read();
  clear.resume(), scene(0);
  EXPECT_GT(image::compare(a, clear.read()).max_diff, 20);
  EXPECT_EQ(fogged.renderer()->stats().draws, 3u);  // the floor, the line, the points
}

// Linear fog from 2 to 12: a black quad facing the eye at depth 7 is half fogged, every pixel of
// it: 0.5 * 255 = 127.5, either neighbour as the factor rounds in float.
TEST(GlslFeatures, LinearFogHalfWayIsHalfTheFogColour) {
  if (!egl_here()) GTEST_SKIP();
  const Pictures p = draw_both(16, 16, [] {
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR), glFogf(GL_FOG_START, 2), glFogf(GL_FOG_END, 12);
    glColor3f(0, 0, 0);
    const float fog_color[4] = {1, 1, 1, 1};
    glFogfv(GL_FOG_COLOR, fog_color);
    glBegin(GL_QUADS);
    glVertex3f(-7, -7, -7), glVertex3f(7, -7, -7), glVertex3f(7, 7, -7), glVertex3f(-7, 7, -7);
    glEnd();
  });
  expect_as_mesa(p);
  for (int y : {1, 8, 14})
    for (int x : {1, 8, 14}) EXPECT_NEAR(rgba(p.glsl, x, y)[0], 127.5, 0.5);
}

// Two copies of a slanted quad, the second through GL_LESS: without an offset it fails
// everywhere (equal depths); pulled forward by glPolygonOffset it passes everywhere; pushed back,
// it fails even through GL_LEQUAL.
void offset_scene(float factor, float units, GLenum func) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(func);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0, 0, -3);
  glRotatef(55, 1, 0.3f, 0);
  auto quad = [] {
    glBegin(GL_QUADS);
    glVertex2f(-1, -1), glVertex2f(1, -1), glVertex2f(1, 1), glVertex2f(-1, 1);
    glEnd();
  };
  glColor3f(1, 0, 0), quad();
  if (factor != 0 || units != 0) glEnable(GL_POLYGON_OFFSET_FILL), glPolygonOffset(factor, units);
  glColor3f(0, 1, 0), quad();
}

TEST(GlslFeatures, PolygonOffsetAsMesaAndByTheRule) {
  if (!egl_here()) GTEST_SKIP();
  struct Case {
    float factor, units;
    GLenum func;
    std::vector<int> centre;
  };
  const Case cases[] = {{0, 0, GL_LESS, {255, 0, 0, 255}},
                        {-1, -1, GL_LESS, {0, 255, 0, 255}},
                        {0, -2, GL_LESS, {0, 255, 0, 255}},
                        {1, 1, GL_LEQUAL, {255, 0, 0, 255}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "offset " << c.factor << ", " << c.units);
    const Pictures p = draw_both(48, 48, [&] { offset_scene(c.factor, c.units, c.func); });
    expect_as_mesa(p);
    EXPECT_EQ(rgba(p.glsl, 24, 24), c.centre);
  }
}

// Lit strips whose material changes between vertices (each face, each parameter, the shininess),
// with two-sided lighting and colour material tracking the diffuse term or not, then a triangle
// after glEnd that keeps the last material. `third`: the face of the ambient and diffuse change.
void material_changes(bool two_side, bool color_material, GLenum third = GL_FRONT_AND_BACK) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glRotatef(25, 1, 0.5f, 0);
  glEnable(GL_LIGHTING), glEnable(GL_LIGHT0), glEnable(GL_LIGHT1);
  const float p1[4] = {0.4f, 0.6f, 1, 1}, spec[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT1, GL_POSITION, p1), glLightfv(GL_LIGHT1, GL_SPECULAR, spec), glLightfv(GL_LIGHT1, GL_DIFFUSE, spec);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two_side);
  if (color_material) glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE), glEnable(GL_COLOR_MATERIAL);
  for (int strip = 0; strip < 2; ++strip) {  // the second wound the other way: its back faces show
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 10; ++i) {
      const float t = float(i) / 9;
      const float m[4] = {t, 1 - t, 0.5f * t + 0.2f, 0.5f + 0.5f * t};
      switch (i % 5) {
        case 1: glMaterialfv(GL_FRONT, GL_DIFFUSE, m); break;
        case 2: glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, m), glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 5 + 30 * t); break;
        case 3: glMaterialfv(third, GL_AMBIENT_AND_DIFFUSE, m); break;
        case 4: glMaterialfv(strip ? GL_BACK : GL_FRONT, GL_EMISSION, m); break;
      }
      glColor3f(0.9f - 0.5f * t, 0.3f + 0.6f * t, 0.6f);
      glNormal3f(0.3f * std::cos(4 * t), 0.3f * std::sin(4 * t), 1);
      const float x = -0.9f + 1.8f * t, y = (strip ? -0.1f : 0.5f) + 0.35f * float((i + strip) % 2);
      glVertex2f(x, y - (strip ? 0.5f : 0.0f));
    }
    glEnd();
  }
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex2f(-0.2f, -0.95f), glVertex2f(0.2f, -0.95f), glVertex2f(0, -0.7f);
  glEnd();
}

TEST(GlslFeatures, MaterialBetweenBeginAndEndAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (bool two_side : {false, true})
    for (bool cm : {false, true}) {
      SCOPED_TRACE(testing::Message() << (two_side ? "two-sided" : "one-sided") << (cm ? ", colour material" : ""));
      const glsl::VertexComparison r = glsl::compare_with_mesa(96, 96, [&] { material_changes(two_side, cm); });
      EXPECT_EQ(r.compared, 17u);  // 8 + 8 strip triangles, the one after
      EXPECT_EQ(r.unpaired, 0u);
      EXPECT_LE(r.max_abs, 1e-5);
      expect_as_mesa(draw_both(96, 96, [&] { material_changes(two_side, cm); }));
    }
}

// A GL_BACK-only ambient, diffuse or specular change inside glBegin under two-sided lighting is a
// departure of Mesa's (its back faces differ by up to 249 steps; GL_FRONT_AND_BACK, GL_FRONT and
// GL_BACK's emission agree): there the backend draws GL's rule, as soft lights each vertex with
// the material current at it: the same picture as soft's, exactly.
TEST(GlslFeatures, BackMaterialBetweenBeginAndEndAsSoft) {
  if (!egl_here()) GTEST_SKIP();
  for (bool cm : {false, true}) {
    auto soft = backends::make("soft");
    backends::GlslBackend ours;
    soft->begin(96, 96), ours.begin(96, 96);
    soft->resume(), material_changes(true, cm, GL_BACK);
    const image::Image want = soft->read();
    ours.resume(), material_changes(true, cm, GL_BACK);
    EXPECT_EQ(image::compare(want, ours.read()).max_diff, 0);
  }
}

// GL's rule: glMaterial inside glBegin/glEnd is no error and the material stays as last set.
TEST(GlslFeatures, MaterialBetweenBeginAndEndStaysAfterwards) {
  if (!egl_here()) GTEST_SKIP();
  backends::GlslBackend b;
  b.begin(8, 8);
  const float red[4] = {1, 0, 0, 1};
  glEnable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glVertex2f(1, 0), glVertex2f(0, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  float d[4], back[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, d);
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, back);
  EXPECT_EQ((std::vector<float>(d, d + 4)), (std::vector<float>{1, 0, 0, 1}));
  EXPECT_FLOAT_EQ(back[0], 0.8f);  // GL's default, untouched
}

// Every polygon primitive, lit two-sided with per-vertex colours, each drawn twice: as given
// (front-facing) and mirrored (back-facing), under the given polygon modes and culling.
void polygon_modes(GLenum front, GLenum back, GLenum shade, GLenum cull) {
  glClearColor(0.1f, 0.1f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glShadeModel(shade);
  glPolygonMode(GL_FRONT, front), glPolygonMode(GL_BACK, back);
  if (cull) glEnable(GL_CULL_FACE), glCullFace(cull);
  glEnable(GL_LIGHTING), glEnable(GL_LIGHT0), glEnable(GL_COLOR_MATERIAL);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  const float back_diffuse[4] = {0.2f, 0.9f, 0.3f, 1};
  glMaterialfv(GL_BACK, GL_DIFFUSE, back_diffuse);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glPointSize(1), glLineWidth(1);
  glTranslatef(0.0123f, 0.0171f, 0);  // no vertex on a pixel's edge (see docs/glsl.md on points)
  const GLenum modes[] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
  for (int m = 0; m < 6; ++m)
    for (int mirror = 0; mirror < 2; ++mirror) {
      const float x0 = -0.93f + 0.31f * float(m), y0 = mirror ? -0.83f : 0.07f;
      glBegin(modes[m]);
      for (int i = 0; i < 8; ++i) {
        const float a = 0.785f * float(i) + 0.1f;
        glColor3f(0.3f + 0.08f * float(i), 0.9f - 0.1f * float(i), 0.5f);
        glNormal3f(0.2f * std::cos(a), 0.2f * std::sin(a), mirror ? -1.0f : 1.0f);
        const bool round = modes[m] == GL_TRIANGLE_FAN || modes[m] == GL_POLYGON;
        const bool quads = modes[m] == GL_QUADS;
        float x = round ? 0.13f + 0.12f * std::cos(a) : quads ? 0.25f * float((i % 4 == 1 || i % 4 == 2)) : 0.037f * float(i);
        float y = round ? 0.37f + 0.35f * std::sin(a)
                        : quads ? 0.37f * float(i / 4) + 0.33f * float(i % 4 >= 2) : 0.33f * float(i % 2) + 0.06f * float(i / 2);
        if (mirror) x = 0.26f - x;  // the winding turned: back-facing
        glVertex2f(x0 + x, y0 + y);
      }
      glEnd();
    }
}

TEST(GlslFeatures, PolygonModesAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  struct Case {
    GLenum front, back, cull;
  };
  const Case cases[] = {{GL_LINE, GL_LINE, 0},  {GL_POINT, GL_POINT, 0}, {GL_FILL, GL_LINE, 0}, {GL_LINE, GL_FILL, 0},
                        {GL_POINT, GL_LINE, 0}, {GL_LINE, GL_POINT, GL_BACK}, {GL_LINE, GL_LINE, GL_FRONT},
                        {GL_FILL, GL_POINT, GL_FRONT_AND_BACK}};
  for (const Case& c : cases)
    for (GLenum shade : {GL_SMOOTH, GL_FLAT}) {
      SCOPED_TRACE(testing::Message() << std::hex << "front 0x" << c.front << " back 0x" << c.back << " cull 0x" << c.cull
                                      << " shade 0x" << shade);
      expect_as_mesa(draw_both(128, 96, [&] { polygon_modes(c.front, c.back, shade, c.cull); }));
    }
}

// What the passes do not draw is said: polygon offset of GL_LINE polygons.
TEST(GlslFeatures, LineModeOffsetIsNamedAsNotDrawn) {
  if (!egl_here()) GTEST_SKIP();
  backends::GlslBackend b;
  b.begin(8, 8);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  const std::set<std::string>& named = b.renderer()->unsupported();
  EXPECT_EQ(named.count("polygon offset of GL_LINE or GL_POINT polygons"), 1u);
  glDisable(GL_POLYGON_OFFSET_LINE);
  EXPECT_EQ(named.size(), 1u);
}

// By the rule: a quad drawn as GL_LINE shows its four sides and not its diagonal.
TEST(GlslFeatures, LineModeQuadHasNoDiagonal) {
  if (!egl_here()) GTEST_SKIP();
  const Pictures p = draw_both(32, 32, [] {
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_QUADS);
    glVertex2f(-0.5f, -0.5f), glVertex2f(0.5f, -0.5f), glVertex2f(0.5f, 0.5f), glVertex2f(-0.5f, 0.5f);
    glEnd();
  });
  expect_as_mesa(p);
  int lit = 0, inside = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool on = rgba(p.glsl, x, y)[0] == 255;
      lit += on;
      inside += on && x >= 10 && x <= 21 && y >= 10 && y <= 21;  // two pixels in from the sides
    }
  EXPECT_EQ(inside, 0);  // no diagonal
  EXPECT_GE(lit, 4 * 15);  // the four sides, 16 pixels each less the shared corners' ends
  EXPECT_EQ(rgba(p.glsl, 16, 16)[0], 0);
}

// A depth-tested quad, an image and a bitmap over it through the raster position (with blending
// and the alpha test on the image), then a quad behind the first: the depth buffer must have come
// through glDrawPixels unchanged for it to stay hidden.
void pixels_and_bitmaps(bool depth_test_pixels) {
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.8f, 0.3f, 0.1f);
  glRectf(-0.6f, -0.6f, 0.2f, 0.2f);  // z = 0
  std::vector<uint8_t> image(20 * 12 * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t((i * 37) % 256);
  if (!depth_test_pixels) glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND), glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glRasterPos3f(-0.3f, -0.1f, 0.5f);
  glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glDisable(GL_BLEND);
  static const GLubyte bits[16] = {0x81, 0x42, 0x24, 0x18, 0x18, 0x24, 0x42, 0x81,
                                   0xFF, 0x00, 0xF0, 0x0F, 0xAA, 0x55, 0x3C, 0xC3};
  glColor3f(0.1f, 0.9f, 0.4f);
  glRasterPos2f(0.3f, 0.3f);
  for (int k = 0; k < 3; ++k) glBitmap(8, 16, 0, 0, 9, 2, bits);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.2f, 0.3f, 0.9f);
  glBegin(GL_QUADS);  // behind the first quad (z = -0.5 is farther): hidden where they overlap
  glVertex3f(-0.4f, -0.4f, -0.5f), glVertex3f(0.7f, -0.4f, -0.5f), glVertex3f(0.7f, 0.7f, -0.5f), glVertex3f(-0.4f, 0.7f, -0.5f);
  glEnd();
}

TEST(GlslFeatures, DrawPixelsAndBitmapAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (bool depth_test : {false, true}) {
    SCOPED_TRACE(depth_test ? "depth-tested pixels" : "pixels without the depth test");
    const Pictures p = draw_both(64, 64, [&] { pixels_and_bitmaps(depth_test); });
    expect_as_mesa(p);
    // The first quad's colour where the far quad overlaps it and nothing else drew (lower left).
    EXPECT_EQ(rgba(p.glsl, 14, 48), (std::vector<int>{204, 76, 26, 255}));
  }
}

}  // namespace
}  // namespace ffc
#endif  // FFCOMPAT_WITH_GLSL
