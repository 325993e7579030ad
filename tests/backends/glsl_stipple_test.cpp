// Line stipple on the GLSL backend (src/backends/glsl/stipple.cpp) against Mesa's fixed-function
// pipeline: GL_LINES, GL_LINE_STRIP and GL_LINE_LOOP under several patterns and factors, smooth
// and flat, flat-on and in perspective, within one 8-bit step; and the pattern's pixels where GL's
// rule decides them outright.
#include <gtest/gtest.h>

#ifdef FFCOMPAT_WITH_GLSL  // a build with EGL
#include <cmath>

#include "egl_here.h"
#include "glsl_pictures.h"
#include "image/compare.h"

namespace ffc::test {
namespace {

struct Pattern {
  GLint factor;
  GLushort bits;
};
const Pattern kPatterns[] = {{1, 0x0F0F}, {3, 0xAAAA}, {2, 0x00FF}};

// A star of lines at many slopes and a zigzag, colours changing along each, in a 96 x 96 window
// whose units are its pixels (vertices off the pixel edges); in perspective, receding through a
// depth-tested wall.
void star(GLenum mode, const Pattern& pat, GLenum shade, float width, bool perspective) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (perspective) {
    glFrustum(-1, 1, -1, 1, 1, 20);
  } else {
    glOrtho(0, 96, 0, 96, -1, 1);
  }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(shade);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(pat.factor, pat.bits);
  glLineWidth(width);
  if (perspective) {  // a wall the lines pass through: their depth decides which pixels show
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.3f, 0.3f, 0.9f);
    glBegin(GL_QUADS);
    glVertex3f(-3, -3, -6.3f), glVertex3f(0.2f, -3, -6.3f), glVertex3f(0.2f, 3, -9.1f), glVertex3f(-3, 3, -9.1f);
    glEnd();
  }
  glBegin(mode);
  for (int i = 0; i < 9; ++i) {
    const float a = 0.7f * float(i);
    glColor3f(0.1f * float(i), 1 - 0.1f * float(i), 0.5f + 0.05f * float(i % 3));
    if (perspective) {
      glVertex3f(0.8f * std::cos(a) + 0.013f, 0.8f * std::sin(a) + 0.021f, -1.5f - 1.7f * float(i));
    } else {
      const float r = i % 2 ? 10.3f : 41.7f;
      glVertex2f(48.2f + r * std::cos(a), 47.9f + r * std::sin(a));
    }
  }
  glEnd();
  glDisable(GL_LINE_STIPPLE);
  glDisable(GL_DEPTH_TEST);
}

TEST(GlslStipple, LinesStripsAndLoopsAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum mode : {GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP})
    for (const Pattern& pat : kPatterns)
      for (GLenum shade : {GL_SMOOTH, GL_FLAT})
        for (float width : {1.0f, 2.0f})
          for (bool perspective : {false, true}) {
            SCOPED_TRACE(testing::Message() << "mode " << mode << " factor " << pat.factor << " pattern 0x" << std::hex
                                            << pat.bits << std::dec << " shade 0x" << std::hex << shade << std::dec
                                            << " width " << width << (perspective ? " perspective" : " flat-on"));
            const Pictures p = draw_both(96, 96, [&] { star(mode, pat, shade, width, perspective); });
            EXPECT_TRUE(p.unsupported.empty()) << p.unsupported.front();
            const image::Diff c = image::compare(p.mesa, p.glsl);
            EXPECT_LE(c.max_diff, 1);
          }
}

// A horizontal line through GL's row 4 of a `w` x 8 window, stippled at factor / 0x00FF: as
// GL_LINES from `from` to `mid` and from `mid` to `w`, or as a strip through the same three points.
Pictures horizontal(GLenum mode, int w, float mid, GLint factor, float from = 0) {
  return draw_both(w, 8, [=] {
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, 8, -1, 1);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(factor, 0x00FF);
    glColor3f(1, 1, 1);
    glBegin(mode);
    glVertex2f(from, 4.5f), glVertex2f(mid, 4.5f);
    if (mode == GL_LINES) glVertex2f(mid, 4.5f);
    glVertex2f(float(w), 4.5f);
    glEnd();
  });
}

bool lit(const image::Image& img, int x) { return img.at(x, 8 - 1 - 4)[0] > 0; }  // GL's row 4

// Two lines of 32 pixels: 0x00FF at factor 2 keeps bits 0 to 7, each 2 pixels long (pixels 0 to
// 15), and drops bits 8 to 15 (16 to 31). The second line starts at bit 0 again either way: as
// GL_LINES it restarts, as a strip it runs on to counter 32, where the 32-pixel pattern repeats.
TEST(GlslStipple, PatternPixelsByTheRule) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum mode : {GL_LINES, GL_LINE_STRIP}) {
    SCOPED_TRACE(testing::Message() << "mode " << mode);
    const Pictures p = horizontal(mode, 64, 32, 2);
    EXPECT_TRUE(p.unsupported.empty());
    for (int x = 1; x < 15; ++x) EXPECT_TRUE(lit(p.glsl, x)) << x;
    for (int x = 17; x < 31; ++x) EXPECT_FALSE(lit(p.glsl, x)) << x;
    for (int x = 33; x < 47; ++x) EXPECT_TRUE(lit(p.glsl, x)) << x;
    for (int x = 49; x < 63; ++x) EXPECT_FALSE(lit(p.glsl, x)) << x;
    EXPECT_LE(image::compare(p.mesa, p.glsl).max_diff, 1);
  }
}

// Two lines of 12 pixels at factor 1: on for pixels 0 .. 7, off for 8 .. 11. A strip's second
// segment runs on from counter 12: dark to counter 15 (x 12 .. 15), lit from 16 (x 16 .. 23);
// GL_LINES' second line starts lit (x 12 .. 19) and goes dark at its ninth pixel (x 20).
TEST(GlslStipple, StripRunsTheCounterOnLinesRestartIt) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum mode : {GL_LINES, GL_LINE_STRIP}) {
    SCOPED_TRACE(testing::Message() << "mode " << mode);
    const Pictures p = horizontal(mode, 24, 12, 1);
    EXPECT_TRUE(lit(p.glsl, 2));
    EXPECT_FALSE(lit(p.glsl, 10));
    EXPECT_EQ(lit(p.glsl, 13), mode == GL_LINES);
    EXPECT_TRUE(lit(p.glsl, 18));
    EXPECT_EQ(lit(p.glsl, 21), mode == GL_LINE_STRIP);
    EXPECT_LE(image::compare(p.mesa, p.glsl).max_diff, 1);
  }
}

// What the pass-through program does not draw yet is said, and the line drawn solid.
TEST(GlslStipple, FogWithStippleIsReported) {
  if (!egl_here()) GTEST_SKIP();
  const Pictures p = draw_both(32, 8, [] {
    glEnable(GL_FOG);
    glEnable(GL_LINE_STIPPLE);
    glBegin(GL_LINES);
    glVertex2f(-0.9f, 0.1f), glVertex2f(0.9f, 0.1f);
    glEnd();
  });
  ASSERT_EQ(p.unsupported.size(), 1u);
  EXPECT_EQ(p.unsupported.front(), "line stipple with fog");
}

// A line from 10 pixels left of the window: the clipper cuts it at the window's left edge, and
// the pattern starts there (pixels 0 .. 15 on, 16 .. 31 off at factor 2), not 10 pixels earlier.
TEST(GlslStipple, PatternStartsWhereTheClipperCuts) {
  if (!egl_here()) GTEST_SKIP();
  const Pictures p = horizontal(GL_LINES, 64, 32, 2, -10);
  EXPECT_TRUE(p.unsupported.empty());
  for (int x = 1; x < 15; ++x) EXPECT_TRUE(lit(p.glsl, x)) << x;
  for (int x = 17; x < 31; ++x) EXPECT_FALSE(lit(p.glsl, x)) << x;
  EXPECT_LE(image::compare(p.mesa, p.glsl).max_diff, 1);
}

// Lines the view volume clips, at the window's sides and across the near and far planes: Mesa
// stipples the clipped line, its pattern starting where the clipper cut it.
TEST(GlslStipple, ClippedLinesAsMesa) {
  if (!egl_here()) GTEST_SKIP();
  for (GLenum mode : {GL_LINES, GL_LINE_STRIP})
    for (GLenum shade : {GL_SMOOTH, GL_FLAT}) {
      SCOPED_TRACE(testing::Message() << "mode " << mode << " shade 0x" << std::hex << shade);
      const Pictures p = draw_both(96, 96, [=] {
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-1, 1, -1, 1, 1, 20);
        glShadeModel(shade);
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(2, 0x0F0F);
        glBegin(mode);
        for (int i = 0; i < 10; ++i) {
          const float a = 1.3f * float(i);
          glColor3f(0.1f * float(i), 1 - 0.1f * float(i), 0.5f);
          glVertex3f(1.9f * std::cos(a) + 0.013f, 1.7f * std::sin(a) + 0.021f, i % 3 == 0 ? -0.4f : -2.5f - 2.9f * float(i));
        }
        glEnd();
      });
      EXPECT_TRUE(p.unsupported.empty()) << p.unsupported.front();
      const image::Diff c = image::compare(p.mesa, p.glsl);
      EXPECT_LE(c.max_diff, 1);
    }
}

}  // namespace
}  // namespace ffc::test
#endif
