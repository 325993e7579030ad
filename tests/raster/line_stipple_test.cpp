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

using picture_test::Difference;
using picture_test::run_both;

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
  int far = 0, inexact = 0, drawn = 0;
  std::string first;
  for (int seed = 0; seed < kCases; ++seed) {
    const Difference d = run_both(kSize, seed, stipple_case);
    far += d.far > 0, inexact += d.inexact, drawn += d.drawn;
    if (d.far && first.empty()) first = d.first + " (" + std::to_string(d.far) + " pixels)";
  }
  EXPECT_EQ(far, 0) << far << " of " << kCases << " cases differ by more than 1; first: " << first;
  EXPECT_GT(drawn, kCases * 40);
  EXPECT_EQ(inexact, 0) << "pixels not identical (measured: none)";
}

}  // namespace
}  // namespace ffc
