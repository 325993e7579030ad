// GL_LINE_STIPPLE against Mesa 22.3 (llvmpipe, whose lines are stippled by the draw module before
// its rasterizer): random patterns and repeat factors over GL_LINES, GL_LINE_STRIP and
// GL_LINE_LOOP (the pattern running on along a strip, starting again for each of GL_LINES),
// widths 1 to 3, flat and smooth, clipped and not. Pictures compared pixel for pixel: identical.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <random>

#include "picture_pair.h"

namespace ffc {
namespace {

constexpr int kSize = 64;

float uni(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

void stipple_case(int seed) {
  std::mt19937 rng(seed);
  glMatrixMode(GL_PROJECTION), glLoadIdentity();
  if (seed % 4 == 3) glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 5), glTranslatef(0, 0, -2);
  glEnable(GL_LINE_STIPPLE);
  const int factors[] = {1, 1, 2, 3, 7};
  glLineStipple(factors[seed % 5], GLushort(std::uniform_int_distribution<int>(1, 0xFFFF)(rng)));
  glLineWidth(float(1 + seed / 5 % 3));
  glShadeModel(seed % 2 ? GL_FLAT : GL_SMOOTH);
  const GLenum modes[] = {GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP};
  glBegin(modes[seed / 3 % 3]);
  const float reach = seed % 7 == 0 ? 1.3f : 0.95f;  // now and then past the edges: clipped
  for (int k = 0; k < 8; ++k) {
    glColor3f(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
    glVertex3f(uni(rng, -reach, reach), uni(rng, -reach, reach), uni(rng, -0.5f, 0.5f));
  }
  glEnd();
}

TEST(LineStipple, PicturesMatchMesa) {
  constexpr int kCases = 300;
  const picture_test::Tally t = picture_test::run_cases(kSize, kCases, stipple_case);
  EXPECT_EQ(t.far_cases, 0) << t.far_cases << " of " << kCases << " cases differ by more than 1; first: " << t.first;
  EXPECT_EQ(t.inexact, 0) << "pixels not identical (measured: none): " << t.first;
  EXPECT_GT(t.drawn, kCases * 40);
}

}  // namespace
}  // namespace ffc
