// glBitmap against Mesa 22.3 (llvmpipe): text drawn as GLUT's bitmap fonts draw it (glRasterPos,
// then one glBitmap a glyph with its origin and advance, GL_UNPACK_ALIGNMENT 1), random glyphs
// at whole and fractional positions, with the unpack state (alignment, row length, skips, LSB
// first), the raster colour latched by glRasterPos, moves with a null bitmap, and the
// per-fragment operations (depth test at the raster depth, blending, alpha test, scissor, colour
// mask). Pictures compared byte for byte.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "picture_pair.h"

namespace ffc {
namespace {

constexpr int kSize = 64;

int pick(std::mt19937& rng, int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
float uni(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

void text_case(int seed) {
  std::mt19937 rng(seed);
  glMatrixMode(GL_PROJECTION), glLoadIdentity();
  if (seed % 3) glOrtho(0, kSize, 0, kSize, -1, 1);  // GLUT programs' usual 2D set-up; else clip space
  glClearColor(0, 0, 0, 0.5f), glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const int align[] = {1, 2, 4, 8};
  glPixelStorei(GL_UNPACK_ALIGNMENT, seed % 4 == 0 ? align[pick(rng, 4)] : 1);
  const int w = 1 + pick(rng, 12), h = 1 + pick(rng, 14);
  int row_length = 0, skip_rows = 0, skip_pixels = 0;
  if (seed % 5 == 1) {
    row_length = w + pick(rng, 9), skip_rows = pick(rng, 3), skip_pixels = pick(rng, 5);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length), glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_pixels);
  }
  if (seed % 7 == 2) glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  switch (seed % 6) {
    case 1: glEnable(GL_DEPTH_TEST), glDepthFunc(seed % 4 ? GL_LESS : GL_GREATER); break;
    case 2: glEnable(GL_BLEND), glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); break;
    case 3: glEnable(GL_ALPHA_TEST), glAlphaFunc(GL_GREATER, 0.5f); break;
    case 4: glEnable(GL_SCISSOR_TEST), glScissor(pick(rng, 20), pick(rng, 20), 10 + pick(rng, 40), 10 + pick(rng, 40)); break;
    case 5: glColorMask(1, 0, 1, 1); break;
  }
  // Glyph data generous enough for any of the unpack states above.
  std::vector<GLubyte> glyphs(4096);
  for (GLubyte& b : glyphs) b = GLubyte(pick(rng, 256));
  for (int line = 0; line < 4; ++line) {
    glColor4f(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
    const float scale = seed % 3 ? 1.0f : 2.0f / kSize, shift = seed % 3 ? 0.0f : -1.0f;
    const bool whole = seed % 2 == 0;
    const float x = whole ? float(pick(rng, 20)) : uni(rng, 0, 20), y = whole ? float(pick(rng, 60)) : uni(rng, 0, 60);
    if (seed % 3 && line == 1) {
      glRasterPos2f(x, y);
    } else {
      glRasterPos2f(x * scale + shift, y * scale + shift);
    }
    glColor4f(1, 1, 1, 1);  // after glRasterPos: the text keeps the latched colour
    for (int c = 0; c < 6; ++c) {
      const float xorig = c % 3 == 0 ? uni(rng, -2, 2) : 0, yorig = c % 4 == 1 ? -2.5f : 0;
      const float xmove = float(w + pick(rng, 3)) + (seed % 4 == 3 ? 0.5f : 0), ymove = c == 5 ? 1.0f : 0;
      glBitmap(w, h, xorig, yorig, xmove, ymove, c == 2 ? nullptr : &glyphs[size_t(c) * 200]);
    }
  }
}

TEST(Bitmap, TextMatchesMesa) {
  constexpr int kCases = 240;
  const picture_test::Tally t = picture_test::run_cases(kSize, kCases, text_case);
  EXPECT_EQ(t.inexact, 0) << t.first;
  EXPECT_GT(t.drawn, kCases * 100);  // glyphs drawn
}

}  // namespace
}  // namespace ffc
