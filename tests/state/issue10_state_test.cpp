// Issue 10's state items against Mesa, each a row that failed before its fix: current values
// after glEnd, glFinish/glFlush inside glBegin/glEnd, the viewport's bounds, NaN in the clamped
// values, glRasterPos/glDrawPixels; and, soft alone, a draw too large for memory.
#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <random>

#include "harness.h"
#include "state/context.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR, IO = GL_INVALID_OPERATION;
const double kNaNd = std::numeric_limits<double>::quiet_NaN();
const float kNaNf = std::numeric_limits<float>::quiet_NaN();

class Issue10 : public ::testing::TestWithParam<Case> {};
TEST_P(Issue10, MatchesMesa) { check_case(GetParam()); }

const GLubyte kImage[5 * 3 * 4] = {
    255, 0, 0, 255,   0, 255, 0, 255,   0, 0, 255, 255,   10, 20, 30, 40,  50, 60, 70, 80,
    90, 100, 110, 120, 130, 140, 150, 160, 170, 180, 190, 200, 210, 220, 230, 240, 250, 1, 2, 3,
    4, 5, 6, 7,       8, 9, 10, 11,       12, 13, 14, 15,     16, 17, 18, 19,  20, 21, 22, 23};
const GLfloat kFloatImage[3 * 2 * 3] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f,
                                        1.5f, -0.5f, 0.25f, 0.33f, 0.66f, 0.99f, 0, 1, 0.5f};

// The fuzzer's strip: a triangle with two equal vertices and one above the view volume, clipped.
void clipped_degenerate_strip() {
  glBegin(GL_TRIANGLE_STRIP);
  glVertex2f(0, 0), glVertex3f(0, 0, 0), glVertex3f(0.84375f, 1.421875f, 0.578125f);
  glEnd();
}

void clipped_line() {
  glBegin(GL_LINES);
  glColor3f(1, 0, 0), glVertex2f(-2, 0.25f), glColor3f(0, 1, 0), glVertex2f(0.5f, -0.5f);
  glEnd();
}

INSTANTIATE_TEST_SUITE_P(State, Issue10, ::testing::ValuesIn(std::vector<Case>{
  // Item 14: a token is written where it fits and counted either way; the count overflows to -1.
  {"FeedbackOverflowOneFloat", nullptr, feedback_into(1, GL_2D, clipped_degenerate_strip), OK},
  {"FeedbackOverflowSeven2D", nullptr, feedback_into(7, GL_2D, clipped_degenerate_strip), OK},
  {"FeedbackFitsClippedStrip", nullptr, feedback_into(40, GL_2D, clipped_degenerate_strip), OK},
  {"FeedbackOverflowClippedLine", nullptr, feedback_into(9, GL_3D_COLOR, clipped_line), OK},
  {"FeedbackFitsClippedLine", nullptr, feedback_into(15, GL_3D_COLOR, clipped_line), OK},
  // Item 3: a glColor / glNormal after the last glVertex of GL_TRIANGLES stays current.
  {"ColourAfterLastVertexOfTriangles", nullptr, [] {
     glBegin(GL_TRIANGLES);
     glVertex3f(0, 0, 0), glVertex3f(1, 0, 0), glVertex3f(0, 1, 0);
     glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
     glNormal3f(0.3f, 0.4f, 0.5f);
     glEnd();
   }, OK},
  {"ColourAfterLastVertexOfTrianglesLit", [] { glEnable(GL_LIGHTING); glEnable(GL_LIGHT0); glEnable(GL_COLOR_MATERIAL); }, [] {
     glBegin(GL_TRIANGLES);
     glColor3f(0.9f, 0.9f, 0.9f);
     glVertex3f(0, 0, 0), glVertex3f(1, 0, 0), glVertex3f(0, 1, 0);
     glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
     glEnd();
   }, OK},
  // Item 4.
  {"FinishInsideBeginEnd", nullptr, inside([] { glFinish(); }), IO},
  {"FlushInsideBeginEnd", nullptr, inside([] { glFlush(); }), IO},
  // Items 8 and 17: the origin clamped to [-32768, 32767], the size to 16384.
  {"ViewportHugeOrigin", nullptr, [] { glViewport(INT_MAX, 0, 10, 10); }, OK},
  {"ViewportHugeNegativeOriginAndSize", nullptr, [] { glViewport(-INT_MAX, -5000000, 100000, 100000); }, OK},
  {"ViewportHugeThenPoint", [] { glViewport(INT_MAX, 0, 10, 10); }, [] {
     glBegin(GL_POINTS);
     glVertex3f(0, 0, 0);
     glEnd();
     observe_picture("picture");
   }, OK},
  {"DepthRangeNaN", nullptr, [] { glDepthRange(kNaNd, 0.5); }, OK},
  {"ClearDepthNaN", nullptr, [] { glClearDepth(kNaNd); }, OK},
  {"ClearColourNaN", nullptr, [] { glClearColor(kNaNf, 2, -1, 0.5f); }, OK},
  // Item 9: glRasterPos2f / glDrawPixels draw on soft as on Mesa.
  {"DrawPixelsAtCorner", nullptr, [] {
     glRasterPos2f(-1, -1);
     glDrawPixels(5, 3, GL_RGBA, GL_UNSIGNED_BYTE, kImage);
     observe_picture("picture");
   }, OK},
  {"DrawPixelsRgbUnaligned", [] { glPixelStorei(GL_UNPACK_ALIGNMENT, 1); }, [] {
     glRasterPos2f(-0.5f, 0.25f);
     glDrawPixels(4, 3, GL_RGB, GL_UNSIGNED_BYTE, kImage);
     observe_picture("picture");
   }, OK},
  {"DrawPixelsFloatRowLength", [] { glPixelStorei(GL_UNPACK_ROW_LENGTH, 3); }, [] {
     glRasterPos2f(0.1f, -0.6f);
     glDrawPixels(2, 2, GL_RGB, GL_FLOAT, kFloatImage);
     observe_picture("picture");
   }, OK},
  {"DrawPixelsLuminanceSkip", [] { glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2); glPixelStorei(GL_UNPACK_SKIP_ROWS, 1); }, [] {
     glRasterPos2f(0, 0);
     glDrawPixels(3, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, kImage);
     observe_picture("picture");
   }, OK},
  {"DrawPixelsRasterPosClipped", nullptr, [] {
     glRasterPos2f(2, 0);  // outside the view volume: no fragments
     glDrawPixels(5, 3, GL_RGBA, GL_UNSIGNED_BYTE, kImage);
     observe_picture("picture");
   }, OK},
  // The raster position's own state in Mesa's corners: NaN, w = 0, w < 0, outside, colours
  // outside [0, 1], lit.
  {"RasterPosNaN", nullptr, [] { glRasterPos2f(std::nanf(""), 0); }, OK},
  {"RasterPosInfinity", nullptr, [] { glRasterPos2f(INFINITY, 0); }, OK},
  {"RasterPosOutsideKeepsTheLast", [] { glRasterPos2f(0.5f, 0.25f); }, [] { glRasterPos2f(2, 0); }, OK},
  {"RasterPosColourUnclamped", [] { glColor4f(std::nanf(""), 0.4f, 2, -1); }, [] { glRasterPos2f(0, 0); }, OK},
  {"RasterPosLit", [] { glEnable(GL_LIGHTING); glEnable(GL_LIGHT0); glTranslatef(0.1f, 0.2f, 0.3f); },
   [] { glRasterPos2f(0.25f, -0.5f); }, OK},
  // A new framebuffer's contents (undefined in GL): llvmpipe's depth starts at 0, so a depth-tested
  // draw before any glClear draws nothing.
  {"NewDepthBufferReadBack", nullptr, [] {
     GLuint d[kWidth * kHeight];
     glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d);
     for (int i = 0; i < kWidth * kHeight; i += 17) observe("depth[" + std::to_string(i) + "]", d[i]);
   }, OK},
  {"DepthTestBeforeAnyClear", [] { glEnable(GL_DEPTH_TEST); }, [] {
     glBegin(GL_TRIANGLES);
     glVertex3f(-1, -1, 0), glVertex3f(1, -1, 0), glVertex3f(0, 1, 0);
     glEnd();
     observe_picture("picture");
   }, OK},
  {"DrawPixelsNegativeSize", nullptr, [] { glDrawPixels(-1, 3, GL_RGBA, GL_UNSIGNED_BYTE, kImage); }, GL_INVALID_VALUE},
  {"DrawPixelsBadFormat", nullptr, [] { glDrawPixels(1, 1, GL_LIGHTING, GL_UNSIGNED_BYTE, kImage); }, GL_INVALID_ENUM},
  {"DrawPixelsInsideBeginEnd", nullptr, inside([] { glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, kImage); }), IO},
}), case_name);

// glRasterPos / glDrawPixels over generated cases: raster positions anywhere in (and past) the
// window, under a random projection; each colour format with bytes or floats; random unpack
// alignment, row length and skips; the depth test on with a random function against a drawn
// triangle. Every byte of the picture must be Mesa's.
std::vector<Case> draw_pixels_cases() {
  static GLfloat floats[64 * 64 * 4];
  static GLubyte bytes[64 * 64 * 4];
  std::mt19937 rng(77);
  for (GLfloat& f : floats) f = float(rng() % 1200) / 1000.0f - 0.1f;  // a few outside [0, 1]
  for (GLubyte& b : bytes) b = GLubyte(rng());
  const GLenum formats[] = {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE,
                            GL_LUMINANCE_ALPHA};
  const GLenum funcs[] = {GL_LESS, GL_LEQUAL, GL_GREATER, GL_GEQUAL, GL_EQUAL, GL_NOTEQUAL, GL_ALWAYS, GL_NEVER};
  auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * float(rng() % 100000) / 100000.0f; };
  std::vector<Case> rows;
  for (int n = 0; n < 200; ++n) {
    const GLenum format = formats[rng() % std::size(formats)];
    const bool as_float = rng() % 2;
    const GLsizei w = 1 + GLsizei(rng() % 9), h = 1 + GLsizei(rng() % 9);
    const GLint align = GLint(1) << (rng() % 4), row_length = rng() % 3 ? 0 : w + GLint(rng() % 4);
    const GLint skip_rows = GLint(rng() % 3), skip_pixels = GLint(rng() % 3);
    const float x = uniform(-1.3f, 1.2f), y = uniform(-1.3f, 1.2f);
    const bool depth = rng() % 2, ortho = rng() % 2;
    const GLenum func = funcs[rng() % std::size(funcs)];
    char name[160];
    std::snprintf(name, sizeof name, "DrawPixels%d_f%04X_%s_%dx%d_a%d_r%d_s%d_%d_at%+.3f_%+.3f_%s_%s%04X", n, format,
                  as_float ? "float" : "ubyte", w, h, align, row_length, skip_rows, skip_pixels, x, y,
                  ortho ? "ortho" : "frustum", depth ? "depth" : "nodepth", func);
    for (char* c = name; *c; ++c)
      if (*c == '+' || *c == '-' || *c == '.') *c = *c == '-' ? 'm' : 'p';
    rows.push_back({name, [=] {
                      glPixelStorei(GL_UNPACK_ALIGNMENT, align);
                      glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length);
                      glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
                      glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_pixels);
                      glMatrixMode(GL_PROJECTION);
                      if (ortho) glOrtho(-1.1, 0.9, -1, 1.2, -1, 1);
                      else glFrustum(-0.5, 0.5, -0.5, 0.5, 0.5, 3), glTranslatef(0, 0, -1.5f);
                      glMatrixMode(GL_MODELVIEW);
                      if (depth) {
                        glClear(GL_DEPTH_BUFFER_BIT);  // a new buffer's contents are undefined (Mesa's: 0)
                        glEnable(GL_DEPTH_TEST);
                        glDepthFunc(GL_ALWAYS);
                        glBegin(GL_TRIANGLES);  // a depth ramp under the pixels
                        glColor3f(0.2f, 0.4f, 0.6f);
                        glVertex3f(-2, -2, -1), glVertex3f(2, -2, 0), glVertex3f(0, 2, 1);
                        glEnd();
                        glDepthFunc(func);
                      }
                      glColor4f(0.9f, 0.1f, 0.5f, 1);
                    },
                    [=] {
                      glRasterPos2f(x, y);
                      glDrawPixels(w, h, format, as_float ? GL_FLOAT : GL_UNSIGNED_BYTE,
                                   as_float ? static_cast<const void*>(floats) : static_cast<const void*>(bytes));
                      observe_picture("picture");
                    },
                    OK});
  }
  return rows;
}
INSTANTIATE_TEST_SUITE_P(Generated, Issue10, ::testing::ValuesIn(draw_pixels_cases()), case_name);

// Item 10: a draw that cannot fit in memory is GL_OUT_OF_MEMORY, not an abort (Mesa would read
// past the arrays; there is nothing of it to compare).
TEST(Issue10Soft, HugeDrawsAreOutOfMemory) {
  state::Context ctx(8, 8);
  state::Context::make_current(&ctx);
  static const GLfloat verts[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  ctx.VertexPointer(3, GL_FLOAT, 0, verts);
  ctx.EnableClientState(GL_VERTEX_ARRAY);
  ctx.DrawArrays(GL_TRIANGLES, 0, INT_MAX);
  EXPECT_EQ(ctx.GetError(), GLenum(GL_OUT_OF_MEMORY));
  const GLuint far_index[3] = {0, 1, 4000000000u};
  ctx.DrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, far_index);
  EXPECT_EQ(ctx.GetError(), GLenum(GL_OUT_OF_MEMORY));
  const GLuint near_index[3] = {1, 2, 4000000000u};  // the other branch: indices not starting at 0
  ctx.DrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, near_index);
  EXPECT_EQ(ctx.GetError(), GLenum(GL_OUT_OF_MEMORY));
  ctx.DrawArrays(GL_TRIANGLES, 0, 3);  // and the context still draws
  EXPECT_EQ(ctx.GetError(), GLenum(GL_NO_ERROR));
  // An enabled array with no pointer (the fuzzer's crash: Mesa reads address 0) reads nothing.
  ctx.EnableClientState(GL_NORMAL_ARRAY);
  ctx.Begin(GL_POINTS);
  ctx.ArrayElement(4);
  ctx.End();
  ctx.DrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(ctx.GetError(), GLenum(GL_INVALID_OPERATION));
  state::Context::make_current(nullptr);
}

// The spec mode tracks the current colour at glEnable(GL_COLOR_MATERIAL), as GL 2.1 section
// 2.14.3 says; the default keeps a glMaterial value sent before it, as Mesa does (docs/deviations.md).
TEST(Issue10Soft, SpecModeTracksColourMaterialAtOnce) {
  for (bool spec : {false, true}) {
    state::Context ctx(8, 8);
    ctx.set_spec(spec);
    const GLfloat m[4] = {0.2f, 0.3f, 0.4f, 1};
    ctx.Materialfv(GL_FRONT, GL_DIFFUSE, m);
    ctx.ColorMaterial(GL_FRONT, GL_DIFFUSE);
    ctx.Enable(GL_COLOR_MATERIAL);
    GLfloat d[4];
    ctx.GetMaterialfv(GL_FRONT, GL_DIFFUSE, d);
    EXPECT_FLOAT_EQ(d[0], spec ? 1.0f : 0.2f) << (spec ? "spec" : "mesa");
    EXPECT_FLOAT_EQ(d[2], spec ? 1.0f : 0.4f) << (spec ? "spec" : "mesa");
  }
}

}  // namespace
}  // namespace ffc::state_test
