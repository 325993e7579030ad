// GL_POINTS on the GLSL backend (src/backends/glsl/points.cpp) against Mesa's fixed function:
// sizes 1 to 4 with centres on and off the rounding ties (x.0, x.25, x.5, x.75 in both axes),
// equal pictures; and one square derived by hand from GL 2.1 section 3.3.1 as llvmpipe rounds it.
#include <gtest/gtest.h>

#ifdef FFCOMPAT_WITH_GLSL  // a build with EGL
#include "backends/glsl/points.h"
#include "egl_here.h"
#include "glsl_pictures.h"
#include "image/compare.h"

namespace ffc::test {
namespace {

// A window whose units are its pixels.
void pixel_units(int w, int h) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

TEST(GlslPoints, WidthRoundsAsLlvmpipe) {
  EXPECT_EQ(glsl::point_width(1.0f), 1);
  EXPECT_EQ(glsl::point_width(1.5f), 1);  // half rounds down
  EXPECT_EQ(glsl::point_width(1.51f), 2);
  EXPECT_EQ(glsl::point_width(0.0f), 1);
  EXPECT_EQ(glsl::point_width(1000.0f), 255);
}

TEST(GlslPoints, SizesOnAndOffTiesAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  const float fractions[] = {0.0f, 0.25f, 0.5f, 0.75f};
  for (GLenum shade : {GL_SMOOTH, GL_FLAT})
    for (int size = 1; size <= 4; ++size) {
      const Pictures p = draw_both(96, 96, [&] {
        pixel_units(96, 96);
        glShadeModel(shade);
        glPointSize(float(size));
        glBegin(GL_POINTS);
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            glColor3f(0.2f + 0.2f * float(i), 1 - 0.2f * float(j), 0.5f);
            glVertex2f(10.0f + 20.0f * float(i) + fractions[i], 10.0f + 20.0f * float(j) + fractions[j]);
          }
        glEnd();
      });
      EXPECT_TRUE(p.unsupported.empty());
      EXPECT_EQ(image::compare(p.mesa, p.glsl).max_diff, 0) << "size " << size << (shade == GL_FLAT ? " flat" : " smooth");
    }
}

// Points are not polygons: two-sided lighting shows their front colours, culling and polygon
// offset leave them alone, whatever the winding the strip drawing them has; fog and the depth
// test apply. Lit, so within 1 step of Mesa.
TEST(GlslPoints, NotCulledOrOffsetFrontColouredFoggedAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum front : {GL_CCW, GL_CW}) {
    const Pictures p = draw_both(64, 64, [&] {
      pixel_units(64, 64);
      glClear(GL_DEPTH_BUFFER_BIT);
      glFrontFace(front);
      glEnable(GL_CULL_FACE), glCullFace(GL_BACK);
      glEnable(GL_POLYGON_OFFSET_FILL), glPolygonOffset(0, -1000);
      glEnable(GL_DEPTH_TEST);
      glEnable(GL_LIGHTING), glEnable(GL_LIGHT0), glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
      const float back[4] = {1, 0, 0, 1};
      glMaterialfv(GL_BACK, GL_DIFFUSE, back);
      glEnable(GL_FOG), glFogi(GL_FOG_MODE, GL_LINEAR), glFogf(GL_FOG_START, -1), glFogf(GL_FOG_END, 3);
      glPointSize(3);
      glNormal3f(0, 0, 1);
      glBegin(GL_POINTS);
      for (int i = 0; i < 6; ++i) glVertex3f(8.0f + 9.0f * float(i) + 0.25f * float(i % 4), 32.5f, -0.9f + 0.3f * float(i));
      glEnd();
    });
    EXPECT_TRUE(p.unsupported.empty());
    EXPECT_LE(image::compare(p.mesa, p.glsl).max_diff, 1) << (front == GL_CW ? "cw" : "ccw");
    EXPECT_GT(p.glsl.at(8, 31)[1], 60);  // drawn, not culled, in the front colour (the back one has almost no green)
  }
}

// A 2-pixel point centred on the pixel centre (15.5, 15.5): an even size takes the square around
// the nearest pixel corner, and on this tie llvmpipe's snapped centre (256 * 15.5 = 3968, plus 128,
// over 256: 16) puts it at columns 15 and 16; rows, counted down with llvmpipe's one-step shift
// (256 * 16.5 - 1 = 4223, plus 128, over 256: 16, less 1), are image rows 15 and 16. The core
// rasterizer's quad [14.5, 16.5] has pixel centres on both side edges, and its left-edge rule
// would take columns 14 and 15.
TEST(GlslPoints, EvenSizeOnAPixelCentreByTheRule) {
  if (!egl_here()) GTEST_SKIP();
  const Pictures p = draw_both(32, 32, [] {
    pixel_units(32, 32);
    glPointSize(2);
    glColor3f(1, 1, 1);
    glBegin(GL_POINTS);
    glVertex2f(15.5f, 15.5f);
    glEnd();
  });
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool inside = x >= 15 && x <= 16 && y >= 15 && y <= 16;
      EXPECT_EQ(p.glsl.at(x, y)[0], inside ? 255 : 0) << x << ", " << y;
    }
  EXPECT_EQ(image::compare(p.mesa, p.glsl).max_diff, 0);
}

}  // namespace
}  // namespace ffc::test
#endif
