// The per-fragment operations against Mesa 22.3 (llvmpipe), generated cases: blending with every
// GL 1.4 factor and equation (glBlendFunc, glBlendFuncSeparate, glBlendEquation(Separate),
// glBlendColor), the alpha test, glColorMask, glDepthMask, the scissor test and glClear under
// masks and the box; over triangles (immediate mode and glDrawArrays, which soft would otherwise
// draw by its triangle-list fast path), lines and points, flat and smooth. Pictures compared
// pixel for pixel: none more than one step apart. The blending arithmetic itself, on colours that
// need no interpolation, is held to every bit.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "picture_pair.h"

namespace ffc {
namespace {

constexpr int kSize = 48;

const GLenum kFactors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
                           GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,
                           GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR,
                           GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA};
const GLenum kEquations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};

float uni(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
int pick(std::mt19937& rng, int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }

// Random primitives: `kind` 0 triangles in immediate mode, 1 triangles by glDrawArrays, 2 lines,
// 3 points; colours with random alpha, z across the depth range.
void primitives(std::mt19937& rng, int kind, int n) {
  std::vector<GLfloat> pos, col;
  for (int k = 0; k < n; ++k) {
    for (int c = 0; c < 4; ++c) col.push_back(uni(rng, -0.1f, 1.1f));
    pos.push_back(uni(rng, -1.1f, 1.1f)), pos.push_back(uni(rng, -1.1f, 1.1f)), pos.push_back(uni(rng, -0.9f, 0.9f));
  }
  if (kind == 1) {
    glEnableClientState(GL_VERTEX_ARRAY), glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos.data()), glColorPointer(4, GL_FLOAT, 0, col.data());
    glDrawArrays(GL_TRIANGLES, 0, n / 3 * 3);
    glDisableClientState(GL_VERTEX_ARRAY), glDisableClientState(GL_COLOR_ARRAY);
    return;
  }
  if (kind == 2) glLineWidth(float(1 + pick(rng, 3)));
  if (kind == 3) glPointSize(float(1 + pick(rng, 4)));
  glBegin(kind == 0 ? GL_TRIANGLES : kind == 2 ? GL_LINES : GL_POINTS);
  for (int k = 0; k < n; ++k) glColor4fv(&col[size_t(k) * 4]), glVertex3fv(&pos[size_t(k) * 3]);
  glEnd();
}

// One case: a background drawn plainly (depth written), the operations of `what` set at random,
// then primitives of each kind through them, and last a plain layer under GL_LESS that shows
// the depth buffer. what: 0 blending (glBlendFunc), 1 separate blending with a constant colour and
// equations, 2 alpha test, 3 colour and depth masks, 4 scissor and clears, 5 all at once.
void fragment_case(int seed) {
  std::mt19937 rng(seed);
  const int what = seed % 6;
  glClearColor(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(seed % 4 == 3 ? GL_FLAT : GL_SMOOTH);
  primitives(rng, 0, 9);
  if (what == 0 || what == 5) {
    glEnable(GL_BLEND);
    glBlendFunc(kFactors[pick(rng, 15)], kFactors[pick(rng, 15)]);
    glBlendColor(uni(rng, -0.2f, 1.2f), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
  }
  if (what == 1) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(kFactors[pick(rng, 15)], kFactors[pick(rng, 15)], kFactors[pick(rng, 15)],
                        kFactors[pick(rng, 15)]);
    glBlendEquationSeparate(kEquations[pick(rng, 5)], kEquations[pick(rng, 5)]);
    glBlendColor(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
  }
  if (what == 2 || what == 5) {
    glEnable(GL_ALPHA_TEST);
    // A reference on a step's half now and then: the test compares 8-bit values.
    glAlphaFunc(GL_NEVER + GLenum(pick(rng, 8)), seed % 3 ? uni(rng, -0.1f, 1.1f) : (pick(rng, 255) + 0.5f) / 255);
  }
  if (what == 3 || what == 5) {
    glColorMask(GLboolean(pick(rng, 2)), GLboolean(pick(rng, 2)), GLboolean(pick(rng, 2)), GLboolean(pick(rng, 2)));
    glDepthMask(GLboolean(pick(rng, 2)));
    glDepthFunc(seed % 2 ? GL_LEQUAL : GL_ALWAYS);
  }
  if (what == 4 || what == 5) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(pick(rng, kSize) - 4, pick(rng, kSize) - 4, pick(rng, kSize), pick(rng, kSize));
    glClearColor(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
    glClearDepth(uni(rng, 0, 1));
    glClear(seed % 3 == 0 ? GL_COLOR_BUFFER_BIT : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  for (int kind = 0; kind < 4; ++kind) primitives(rng, kind, kind == 3 ? 12 : 6);
  glDisable(GL_BLEND), glDisable(GL_ALPHA_TEST), glDisable(GL_SCISSOR_TEST);
  glColorMask(1, 1, 1, 1), glDepthMask(1), glDepthFunc(GL_LESS);
  primitives(rng, 0, 6);
}

TEST(FragmentOps, PicturesMatchMesa) {
  constexpr int kCases = 360;
  const picture_test::Tally t = picture_test::run_cases(kSize, kCases, fragment_case);
  EXPECT_EQ(t.far_cases, 0) << t.far_cases << " of " << kCases << " cases differ by more than 1; first: " << t.first;
  // The same cases without the operations differ in 17 single pixels by one step (colour
  // interpolation of lines and points); with them, in 12.
  EXPECT_LE(t.inexact, 24) << "pixels not identical";
  EXPECT_GT(t.drawn, kCases * kSize * kSize / 2);
}

// Every source byte against every destination byte for each of the 225 factor pairs and each
// equation: points (whose colour is their vertex's, exactly k / 255 plus a random fraction of a
// step) over a background of points; alpha and constant colour random per pair. Bit for bit.
void blend_grid(int seed) {
  std::mt19937 rng(seed);
  constexpr int n = 64;
  glMatrixMode(GL_PROJECTION), glLoadIdentity(), glOrtho(0, n, 0, n, -1, 1);
  const float dst_alpha = float(pick(rng, 256)) / 255, src_alpha = uni(rng, 0, 1), frac = uni(rng, 0, 1);
  glBegin(GL_POINTS);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) glColor4f(y * 4 / 255.0f, 1 - y * 4 / 255.0f, x * 4 / 255.0f, dst_alpha), glVertex2f(x + 0.5f, y + 0.5f);
  glEnd();
  glEnable(GL_BLEND);
  if (seed < 225) glBlendFunc(kFactors[seed % 15], kFactors[seed / 15]);
  else glBlendFuncSeparate(kFactors[pick(rng, 15)], kFactors[pick(rng, 15)], kFactors[pick(rng, 15)], kFactors[pick(rng, 15)]);
  glBlendEquationSeparate(seed < 225 ? GL_FUNC_ADD : kEquations[seed % 5], seed < 225 ? GL_FUNC_ADD : kEquations[seed / 5 % 5]);
  glBlendColor(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
  glBegin(GL_POINTS);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float v = (x * 4 + frac) / 255.0f;
      glColor4f(v, 1 - v, (y * 4 + frac) / 255.0f, src_alpha), glVertex2f(x + 0.5f, y + 0.5f);
    }
  glEnd();
}

TEST(FragmentOps, BlendingBitExact) {
  const picture_test::Tally t = picture_test::run_cases(64, 225 + 50, blend_grid);
  EXPECT_EQ(t.inexact, 0) << t.first;
}

// glDrawPixels through the operations: a random image (bytes or floats, RGBA or RGB) at a random
// raster position over a drawn background, under blending, the alpha test, the scissor box or
// the masks. Bit for bit.
void draw_pixels_case(int seed) {
  std::mt19937 rng(seed);
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f), glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(GL_FLAT);  // a background whose pixels match Mesa's exactly
  glEnable(GL_DEPTH_TEST), glDepthFunc(GL_ALWAYS);
  primitives(rng, 0, 9);
  glDisable(GL_DEPTH_TEST), glDepthFunc(GL_LESS);
  switch (seed % 4) {
    case 0:
      glEnable(GL_BLEND);
      glBlendFuncSeparate(kFactors[pick(rng, 15)], kFactors[pick(rng, 15)], kFactors[pick(rng, 15)], kFactors[pick(rng, 15)]);
      glBlendColor(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
      break;
    case 1: glEnable(GL_ALPHA_TEST), glAlphaFunc(GL_NEVER + GLenum(pick(rng, 8)), uni(rng, 0, 1)); break;
    case 2: glEnable(GL_SCISSOR_TEST), glScissor(pick(rng, 30), pick(rng, 30), pick(rng, 30), pick(rng, 30)); break;
    case 3:
      glColorMask(GLboolean(pick(rng, 2)), GLboolean(pick(rng, 2)), GLboolean(pick(rng, 2)), GLboolean(pick(rng, 2)));
      glEnable(GL_DEPTH_TEST), glDepthMask(GL_FALSE), glDepthFunc(GL_LEQUAL);
      break;
  }
  const int w = 1 + pick(rng, 40), h = 1 + pick(rng, 40);
  const bool floats = seed % 3 == 0, rgb = seed % 5 == 0;
  std::vector<GLubyte> bytes(size_t(w) * h * 4);
  std::vector<GLfloat> fl(bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = GLubyte(pick(rng, 256)), fl[i] = uni(rng, -0.1f, 1.1f);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2f(uni(rng, -1, 0.5f), uni(rng, -1, 0.5f));
  glDrawPixels(w, h, rgb ? GL_RGB : GL_RGBA, floats ? GL_FLOAT : GL_UNSIGNED_BYTE,
               floats ? static_cast<const void*>(fl.data()) : bytes.data());
  glDisable(GL_DEPTH_TEST), glDepthMask(GL_TRUE);
  glColorMask(1, 1, 1, 1);
}

TEST(FragmentOps, DrawPixelsBitExact) {
  const picture_test::Tally t = picture_test::run_cases(kSize, 160, draw_pixels_case);
  EXPECT_EQ(t.inexact, 0) << t.first;
}

}  // namespace
}  // namespace ffc
